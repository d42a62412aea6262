build-tsan/src/core/precond_hodlr.o: src/core/precond_hodlr.c \
 include/adhere/precond.h include/adhere/hodlr.h include/adhere/status.h
include/adhere/precond.h:
include/adhere/hodlr.h:
include/adhere/status.h:
