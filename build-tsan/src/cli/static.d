build-tsan/src/cli/static.o: src/cli/static.c src/cli/static.h \
 include/adhere/runner.h include/adhere/drive.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/static.h include/adhere/folds.h src/scene/config.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 include/adhere/status.h
src/cli/static.h:
include/adhere/runner.h:
include/adhere/drive.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rule.h:
include/adhere/static.h:
include/adhere/folds.h:
src/scene/config.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
include/adhere/status.h:
