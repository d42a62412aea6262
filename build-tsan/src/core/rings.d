build-tsan/src/core/rings.o: src/core/rings.c include/adhere/rings.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/models.h \
 include/adhere/status.h include/adhere/units.h
include/adhere/rings.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/models.h:
include/adhere/status.h:
include/adhere/units.h:
