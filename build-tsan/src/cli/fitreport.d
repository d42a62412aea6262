build-tsan/src/cli/fitreport.o: src/cli/fitreport.c src/cli/fitreport.h \
 include/adhere/fit.h include/adhere/fitmodel.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h include/adhere/relax.h \
 include/adhere/state.h include/adhere/static.h include/adhere/folds.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 src/plot/outdir.h src/scene/config.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/scene/fitdata.h \
 src/scene/measured.h include/adhere/models.h include/adhere/status.h \
 src/plot/fitplot.h
src/cli/fitreport.h:
include/adhere/fit.h:
include/adhere/fitmodel.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/relax.h:
include/adhere/state.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
src/plot/outdir.h:
src/scene/config.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/scene/fitdata.h:
src/scene/measured.h:
include/adhere/models.h:
include/adhere/status.h:
src/plot/fitplot.h:
