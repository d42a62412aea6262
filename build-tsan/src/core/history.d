build-tsan/src/core/history.o: src/core/history.c \
 include/adhere/history.h include/adhere/drive.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/status.h
include/adhere/history.h:
include/adhere/drive.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rule.h:
include/adhere/status.h:
