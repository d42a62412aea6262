build-tsan/src/core/kernel_dense.o: src/core/kernel_dense.c \
 include/adhere/status.h src/core/kernel.h include/adhere/kernel.h \
 include/adhere/grid.h include/adhere/params.h
include/adhere/status.h:
src/core/kernel.h:
include/adhere/kernel.h:
include/adhere/grid.h:
include/adhere/params.h:
