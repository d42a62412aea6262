build-tsan/src/core/visco_params.o: src/core/visco_params.c \
 include/adhere/visco.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/status.h
include/adhere/visco.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/status.h:
