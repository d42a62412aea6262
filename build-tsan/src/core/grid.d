build-tsan/src/core/grid.o: src/core/grid.c include/adhere/grid.h \
 include/adhere/params.h include/adhere/models.h include/adhere/status.h \
 include/adhere/units.h
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/models.h:
include/adhere/status.h:
include/adhere/units.h:
