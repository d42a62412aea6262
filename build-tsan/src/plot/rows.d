build-tsan/src/plot/rows.o: src/plot/rows.c src/plot/rows.h \
 include/adhere/observe.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/state.h
src/plot/rows.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
