build-tsan/src/core/fgmres.o: src/core/fgmres.c include/adhere/fgmres.h \
 include/adhere/status.h
include/adhere/fgmres.h:
include/adhere/status.h:
