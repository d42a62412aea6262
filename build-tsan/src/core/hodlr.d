build-tsan/src/core/hodlr.o: src/core/hodlr.c include/adhere/hodlr.h \
 include/adhere/status.h
include/adhere/hodlr.h:
include/adhere/status.h:
