build-tsan/src/core/rule.o: src/core/rule.c include/adhere/rule.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 include/adhere/observe.h include/adhere/state.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/status.h
include/adhere/rule.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/status.h:
