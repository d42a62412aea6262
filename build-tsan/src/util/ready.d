build-tsan/src/util/ready.o: src/util/ready.c src/util/ready.h
src/util/ready.h:
