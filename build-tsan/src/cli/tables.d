build-tsan/src/cli/tables.o: src/cli/tables.c src/cli/tables.h \
 include/adhere/protocol.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/state.h \
 include/adhere/static.h include/adhere/folds.h include/adhere/kernel.h \
 src/scene/config.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/plot/outdir.h \
 src/plot/rows.h include/adhere/cycle.h include/adhere/models.h \
 include/adhere/status.h
src/cli/tables.h:
include/adhere/protocol.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/kernel.h:
src/scene/config.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/plot/outdir.h:
src/plot/rows.h:
include/adhere/cycle.h:
include/adhere/models.h:
include/adhere/status.h:
