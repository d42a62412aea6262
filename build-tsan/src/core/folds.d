build-tsan/src/core/folds.o: src/core/folds.c include/adhere/folds.h
include/adhere/folds.h:
