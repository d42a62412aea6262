build-tsan/src/tui/sim.o: src/tui/sim.c src/tui/sim.h \
 include/adhere/cycle.h include/adhere/observe.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/state.h include/adhere/run.h \
 include/adhere/drive.h include/adhere/kernel.h include/adhere/protocol.h \
 include/adhere/relax.h include/adhere/rule.h include/adhere/static.h \
 include/adhere/folds.h include/adhere/history.h include/adhere/models.h \
 include/adhere/units.h include/adhere/visco.h src/scene/config.h \
 include/adhere/rings.h src/scene/figures.h include/adhere/clock.h \
 include/adhere/maugis.h include/adhere/rule_static.h \
 include/adhere/rule_visco.h include/adhere/status.h src/scene/budget.h
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
include/adhere/clock.h:
include/adhere/maugis.h:
include/adhere/rule_static.h:
include/adhere/rule_visco.h:
include/adhere/status.h:
src/scene/budget.h:
