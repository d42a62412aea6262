build-tsan/src/cli/cost.o: src/cli/cost.c src/cli/cost.h \
 src/cli/options.h src/scene/config.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h include/adhere/cycle.h \
 include/adhere/clock.h include/adhere/runner.h include/adhere/drive.h \
 include/adhere/rule.h include/adhere/static.h include/adhere/folds.h \
 include/adhere/status.h src/cli/exit.h src/cli/interrupt.h \
 src/util/ready.h src/cli/progress.h src/cli/static.h src/cli/tables.h \
 src/plot/gnuplot.h src/plot/labels.h src/plot/outdir.h src/plot/plot.h \
 src/plot/setup.h src/scene/measured.h src/plot/session.h \
 src/scene/budget.h
src/cli/cost.h:
src/cli/options.h:
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
include/adhere/cycle.h:
include/adhere/clock.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/status.h:
src/cli/exit.h:
src/cli/interrupt.h:
src/util/ready.h:
src/cli/progress.h:
src/cli/static.h:
src/cli/tables.h:
src/plot/gnuplot.h:
src/plot/labels.h:
src/plot/outdir.h:
src/plot/plot.h:
src/plot/setup.h:
src/scene/measured.h:
src/plot/session.h:
src/scene/budget.h:
