build-tsan/src/plot/labels.o: src/plot/labels.c src/plot/labels.h
src/plot/labels.h:
