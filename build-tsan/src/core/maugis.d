build-tsan/src/core/maugis.o: src/core/maugis.c include/adhere/maugis.h \
 include/adhere/models.h include/adhere/params.h include/adhere/status.h
include/adhere/maugis.h:
include/adhere/models.h:
include/adhere/params.h:
include/adhere/status.h:
