build-tsan/src/core/models.o: src/core/models.c include/adhere/models.h \
 include/adhere/params.h include/adhere/status.h
include/adhere/models.h:
include/adhere/params.h:
include/adhere/status.h:
