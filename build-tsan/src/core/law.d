build-tsan/src/core/law.o: src/core/law.c include/adhere/law.h
include/adhere/law.h:
