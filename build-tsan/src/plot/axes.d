build-tsan/src/plot/axes.o: src/plot/axes.c src/plot/axes.h
src/plot/axes.h:
