build-tsan/src/core/params.o: src/core/params.c include/adhere/params.h \
 include/adhere/status.h include/adhere/units.h
include/adhere/params.h:
include/adhere/status.h:
include/adhere/units.h:
