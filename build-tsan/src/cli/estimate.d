build-tsan/src/cli/estimate.o: src/cli/estimate.c src/cli/estimate.h \
 src/scene/config.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 src/scene/plan.h include/adhere/clock.h src/cli/progress.h
src/cli/estimate.h:
src/scene/config.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/scene/plan.h:
include/adhere/clock.h:
src/cli/progress.h:
