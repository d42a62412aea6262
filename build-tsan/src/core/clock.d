build-tsan/src/core/clock.o: src/core/clock.c include/adhere/clock.h
include/adhere/clock.h:
