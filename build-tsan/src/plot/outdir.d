build-tsan/src/plot/outdir.o: src/plot/outdir.c src/plot/outdir.h
src/plot/outdir.h:
