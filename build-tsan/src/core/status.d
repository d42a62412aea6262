build-tsan/src/core/status.o: src/core/status.c include/adhere/status.h
include/adhere/status.h:
