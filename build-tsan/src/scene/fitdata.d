build-tsan/src/scene/fitdata.o: src/scene/fitdata.c \
 include/adhere/units.h src/scene/fitdata.h include/adhere/fitmodel.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 include/adhere/relax.h include/adhere/state.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h src/scene/measured.h include/adhere/models.h
include/adhere/units.h:
src/scene/fitdata.h:
include/adhere/fitmodel.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/relax.h:
include/adhere/state.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
src/scene/measured.h:
include/adhere/models.h:
