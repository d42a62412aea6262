build-tsan/src/core/visco_flow.o: src/core/visco_flow.c src/core/visco.h \
 include/adhere/visco.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h src/core/visco_pre.h \
 include/adhere/status.h
src/core/visco.h:
include/adhere/visco.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
src/core/visco_pre.h:
include/adhere/status.h:
