build-tsan/src/cli/runout.o: src/cli/runout.c src/cli/runout.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/state.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/kernel.h include/adhere/protocol.h \
 src/cli/timerun.h include/adhere/runner.h include/adhere/drive.h \
 include/adhere/relax.h include/adhere/rule.h include/adhere/visco.h \
 src/cli/tables.h src/scene/config.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/plot/outdir.h \
 include/adhere/status.h src/cli/exit.h src/cli/figures.h \
 src/cli/studyrow.h src/cli/interrupt.h src/plot/plot.h src/plot/setup.h \
 src/scene/measured.h
src/cli/runout.h:
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
include/adhere/status.h:
src/cli/exit.h:
src/cli/figures.h:
src/cli/studyrow.h:
src/cli/interrupt.h:
src/plot/plot.h:
src/plot/setup.h:
src/scene/measured.h:
