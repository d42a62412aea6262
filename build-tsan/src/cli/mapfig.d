build-tsan/src/cli/mapfig.o: src/cli/mapfig.c src/cli/mapfig.h \
 src/cli/studyrow.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/state.h \
 include/adhere/static.h include/adhere/folds.h include/adhere/kernel.h \
 include/adhere/protocol.h src/cli/timerun.h include/adhere/runner.h \
 include/adhere/drive.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/visco.h src/cli/tables.h src/scene/config.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 src/plot/outdir.h src/plot/session.h src/plot/gnuplot.h \
 src/plot/labels.h
src/cli/mapfig.h:
src/cli/studyrow.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
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
src/plot/session.h:
src/plot/gnuplot.h:
src/plot/labels.h:
