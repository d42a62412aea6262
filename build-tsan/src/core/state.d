build-tsan/src/core/state.o: src/core/state.c include/adhere/state.h
include/adhere/state.h:
