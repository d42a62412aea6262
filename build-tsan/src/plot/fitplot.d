build-tsan/src/plot/fitplot.o: src/plot/fitplot.c src/plot/fitplot.h \
 src/plot/outdir.h src/plot/gnuplot.h src/plot/labels.h \
 src/plot/session.h
src/plot/fitplot.h:
src/plot/outdir.h:
src/plot/gnuplot.h:
src/plot/labels.h:
src/plot/session.h:
