build-tsan/src/core/cycle.o: src/core/cycle.c include/adhere/cycle.h \
 include/adhere/observe.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/state.h include/adhere/run.h
include/adhere/cycle.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
include/adhere/run.h:
