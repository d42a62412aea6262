build-tsan/src/tui/plotpath.o: src/tui/plotpath.c src/tui/plotpath.h \
 src/tui/sim.h include/adhere/cycle.h include/adhere/observe.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/state.h \
 include/adhere/run.h include/adhere/drive.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/static.h include/adhere/folds.h include/adhere/history.h \
 include/adhere/models.h include/adhere/units.h include/adhere/visco.h \
 src/scene/config.h include/adhere/rings.h src/scene/figures.h \
 src/plot/outdir.h src/plot/setup.h src/scene/measured.h src/plot/plot.h
src/tui/plotpath.h:
src/tui/sim.h:
include/adhere/cycle.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
include/adhere/run.h:
include/adhere/drive.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/relax.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/history.h:
include/adhere/models.h:
include/adhere/units.h:
include/adhere/visco.h:
src/scene/config.h:
include/adhere/rings.h:
src/scene/figures.h:
src/plot/outdir.h:
src/plot/setup.h:
src/scene/measured.h:
src/plot/plot.h:
