build-tsan/src/cli/fit.o: src/cli/fit.c src/cli/fit.h src/cli/options.h \
 src/scene/config.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 include/adhere/fit.h include/adhere/fitmodel.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/status.h src/cli/advice.h \
 src/cli/batch.h src/cli/exit.h src/cli/fitreport.h src/plot/outdir.h \
 src/scene/fitdata.h src/scene/measured.h src/cli/interrupt.h \
 include/adhere/runner.h include/adhere/drive.h include/adhere/rule.h \
 src/util/ready.h src/scene/budget.h
src/cli/fit.h:
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
include/adhere/fit.h:
include/adhere/fitmodel.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/status.h:
src/cli/advice.h:
src/cli/batch.h:
src/cli/exit.h:
src/cli/fitreport.h:
src/plot/outdir.h:
src/scene/fitdata.h:
src/scene/measured.h:
src/cli/interrupt.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/rule.h:
src/util/ready.h:
src/scene/budget.h:
