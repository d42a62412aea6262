build-tsan/src/core/static_qstep.o: src/core/static_qstep.c \
 src/core/static.h include/adhere/fgmres.h include/adhere/folds.h \
 include/adhere/precond.h include/adhere/static.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/rings.h include/adhere/status.h
src/core/static.h:
include/adhere/fgmres.h:
include/adhere/folds.h:
include/adhere/precond.h:
include/adhere/static.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/rings.h:
include/adhere/status.h:
