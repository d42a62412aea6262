build-tsan/src/plot/gnuplot.o: src/plot/gnuplot.c src/plot/gnuplot.h \
 include/adhere/clock.h
src/plot/gnuplot.h:
include/adhere/clock.h:
