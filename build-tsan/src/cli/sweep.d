build-tsan/src/cli/sweep.o: src/cli/sweep.c src/cli/sweep.h \
 src/cli/kcache.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h src/scene/config.h include/adhere/protocol.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/state.h \
 include/adhere/relax.h include/adhere/rings.h include/adhere/units.h \
 src/scene/figures.h src/cli/options.h src/plot/outdir.h \
 include/adhere/clock.h include/adhere/runner.h include/adhere/drive.h \
 include/adhere/rule.h include/adhere/static.h include/adhere/folds.h \
 include/adhere/status.h src/cli/studycost.h src/scene/plan.h \
 src/cli/exit.h src/cli/figures.h src/cli/studyrow.h src/cli/timerun.h \
 include/adhere/visco.h src/cli/tables.h src/cli/interrupt.h \
 src/cli/progress.h src/cli/runout.h src/cli/static.h src/cli/study.h \
 src/scene/budget.h src/util/ready.h
src/cli/sweep.h:
src/cli/kcache.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
src/scene/config.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/cli/options.h:
src/plot/outdir.h:
include/adhere/clock.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/status.h:
src/cli/studycost.h:
src/scene/plan.h:
src/cli/exit.h:
src/cli/figures.h:
src/cli/studyrow.h:
src/cli/timerun.h:
include/adhere/visco.h:
src/cli/tables.h:
src/cli/interrupt.h:
src/cli/progress.h:
src/cli/runout.h:
src/cli/static.h:
src/cli/study.h:
src/scene/budget.h:
src/util/ready.h:
