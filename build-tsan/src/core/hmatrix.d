build-tsan/src/core/hmatrix.o: src/core/hmatrix.c \
 include/adhere/hmatrix.h include/adhere/status.h
include/adhere/hmatrix.h:
include/adhere/status.h:
