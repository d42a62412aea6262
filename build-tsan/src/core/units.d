build-tsan/src/core/units.o: src/core/units.c include/adhere/units.h \
 include/adhere/status.h
include/adhere/units.h:
include/adhere/status.h:
