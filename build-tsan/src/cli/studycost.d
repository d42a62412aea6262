build-tsan/src/cli/studycost.o: src/cli/studycost.c src/cli/studycost.h \
 src/scene/config.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 src/scene/plan.h include/adhere/clock.h include/adhere/runner.h \
 include/adhere/drive.h include/adhere/rule.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/status.h src/cli/progress.h \
 src/cli/static.h
src/cli/studycost.h:
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
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/status.h:
src/cli/progress.h:
src/cli/static.h:
