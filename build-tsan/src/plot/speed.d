build-tsan/src/plot/speed.o: src/plot/speed.c src/plot/speed.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/state.h
src/plot/speed.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
