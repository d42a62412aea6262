build-tsan/src/core/precond_dense.o: src/core/precond_dense.c \
 include/adhere/precond.h include/adhere/status.h
include/adhere/precond.h:
include/adhere/status.h:
