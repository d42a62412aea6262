build-tsan/src/core/run.o: src/core/run.c include/adhere/run.h \
 include/adhere/observe.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/state.h include/adhere/status.h include/adhere/units.h
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
include/adhere/status.h:
include/adhere/units.h:
