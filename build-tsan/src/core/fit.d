build-tsan/src/core/fit.o: src/core/fit.c include/adhere/fit.h \
 include/adhere/fitmodel.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/relax.h include/adhere/state.h \
 include/adhere/static.h include/adhere/folds.h include/adhere/protocol.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/models.h \
 include/adhere/status.h
include/adhere/fit.h:
include/adhere/fitmodel.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/relax.h:
include/adhere/state.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/models.h:
include/adhere/status.h:
