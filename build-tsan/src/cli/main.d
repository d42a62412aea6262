build-tsan/src/cli/main.o: src/cli/main.c include/adhere/grid.h \
 include/adhere/params.h src/cli/advice.h src/cli/batch.h src/cli/exit.h \
 src/cli/options.h src/scene/config.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/cli/cost.h \
 src/cli/estimate.h src/scene/plan.h src/cli/data.h src/cli/fit.h \
 src/cli/studycost.h src/cli/study.h src/cli/studyrow.h \
 include/adhere/static.h include/adhere/folds.h src/cli/timerun.h \
 include/adhere/runner.h include/adhere/drive.h include/adhere/rule.h \
 include/adhere/visco.h src/cli/tables.h src/plot/outdir.h \
 src/cli/merge.h src/cli/interrupt.h src/scene/budget.h src/cli/static.h \
 src/tui/actions.h src/tui/tui.h
include/adhere/grid.h:
include/adhere/params.h:
src/cli/advice.h:
src/cli/batch.h:
src/cli/exit.h:
src/cli/options.h:
src/scene/config.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/cli/cost.h:
src/cli/estimate.h:
src/scene/plan.h:
src/cli/data.h:
src/cli/fit.h:
src/cli/studycost.h:
src/cli/study.h:
src/cli/studyrow.h:
include/adhere/static.h:
include/adhere/folds.h:
src/cli/timerun.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/visco.h:
src/cli/tables.h:
src/plot/outdir.h:
src/cli/merge.h:
src/cli/interrupt.h:
src/scene/budget.h:
src/cli/static.h:
src/tui/actions.h:
src/tui/tui.h:
