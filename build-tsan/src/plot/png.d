build-tsan/src/plot/png.o: src/plot/png.c src/plot/png.h \
 src/plot/gnuplot.h src/plot/outdir.h src/plot/labels.h \
 build-tsan/gen/style.inc
src/plot/png.h:
src/plot/gnuplot.h:
src/plot/outdir.h:
src/plot/labels.h:
build-tsan/gen/style.inc:
