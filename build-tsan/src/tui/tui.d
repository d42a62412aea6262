build-tsan/src/tui/tui.o: src/tui/tui.c src/tui/tui.h src/scene/config.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h include/adhere/clock.h \
 include/adhere/status.h src/tui/actions.h src/tui/keysrc.h \
 src/tui/replay.h src/tui/plotpath.h src/tui/sim.h include/adhere/cycle.h \
 include/adhere/drive.h include/adhere/rule.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/history.h include/adhere/models.h \
 include/adhere/visco.h src/tui/screen.h src/plot/outdir.h \
 src/plot/rows.h src/util/ready.h
src/tui/tui.h:
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
include/adhere/clock.h:
include/adhere/status.h:
src/tui/actions.h:
src/tui/keysrc.h:
src/tui/replay.h:
src/tui/plotpath.h:
src/tui/sim.h:
include/adhere/cycle.h:
include/adhere/drive.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/history.h:
include/adhere/models.h:
include/adhere/visco.h:
src/tui/screen.h:
src/plot/outdir.h:
src/plot/rows.h:
src/util/ready.h:
