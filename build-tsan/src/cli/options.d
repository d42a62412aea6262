build-tsan/src/cli/options.o: src/cli/options.c src/cli/options.h \
 src/scene/config.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 include/adhere/drive.h include/adhere/rule.h include/adhere/status.h \
 src/cli/advice.h src/cli/studyrow.h include/adhere/static.h \
 include/adhere/folds.h src/cli/timerun.h include/adhere/runner.h \
 include/adhere/visco.h src/cli/tables.h src/plot/outdir.h \
 src/scene/scene.h
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
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/status.h:
src/cli/advice.h:
src/cli/studyrow.h:
include/adhere/static.h:
include/adhere/folds.h:
src/cli/timerun.h:
include/adhere/runner.h:
include/adhere/visco.h:
src/cli/tables.h:
src/plot/outdir.h:
src/scene/scene.h:
