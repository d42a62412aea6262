build-tsan/src/core/visco_pre.o: src/core/visco_pre.c \
 src/core/visco_pre.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/hodlr.h include/adhere/status.h
src/core/visco_pre.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/hodlr.h:
include/adhere/status.h:
