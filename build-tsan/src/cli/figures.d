build-tsan/src/cli/figures.o: src/cli/figures.c src/cli/figures.h \
 include/adhere/protocol.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/state.h \
 src/cli/studyrow.h include/adhere/static.h include/adhere/folds.h \
 include/adhere/kernel.h src/cli/timerun.h include/adhere/runner.h \
 include/adhere/drive.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/visco.h src/cli/tables.h src/scene/config.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 src/plot/outdir.h include/adhere/cycle.h include/adhere/models.h \
 src/cli/jumps.h src/cli/mapfig.h src/plot/session.h src/plot/gnuplot.h \
 src/plot/axes.h src/plot/labels.h src/plot/plot.h src/plot/setup.h \
 src/scene/measured.h
src/cli/figures.h:
include/adhere/protocol.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
src/cli/studyrow.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/kernel.h:
src/cli/timerun.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/relax.h:
include/adhere/rule.h:
include/adhere/visco.h:
src/cli/tables.h:
src/scene/config.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/plot/outdir.h:
include/adhere/cycle.h:
include/adhere/models.h:
src/cli/jumps.h:
src/cli/mapfig.h:
src/plot/session.h:
src/plot/gnuplot.h:
src/plot/axes.h:
src/plot/labels.h:
src/plot/plot.h:
src/plot/setup.h:
src/scene/measured.h:
