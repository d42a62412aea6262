build-tsan/src/core/kernel_hier.o: src/core/kernel_hier.c \
 include/adhere/h2.h include/adhere/hmatrix.h include/adhere/rings.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/status.h \
 src/core/kernel.h include/adhere/kernel.h
include/adhere/h2.h:
include/adhere/hmatrix.h:
include/adhere/rings.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/status.h:
src/core/kernel.h:
include/adhere/kernel.h:
