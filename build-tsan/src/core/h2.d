build-tsan/src/core/h2.o: src/core/h2.c include/adhere/h2.h \
 include/adhere/status.h src/core/h2_product.h
include/adhere/h2.h:
include/adhere/status.h:
src/core/h2_product.h:
