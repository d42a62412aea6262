build-tsan/src/core/kernel.o: src/core/kernel.c include/adhere/kernel.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/status.h \
 src/core/kernel.h
include/adhere/kernel.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/status.h:
src/core/kernel.h:
