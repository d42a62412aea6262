build-tsan/src/core/precond.o: src/core/precond.c \
 include/adhere/precond.h include/adhere/status.h
include/adhere/precond.h:
include/adhere/status.h:
