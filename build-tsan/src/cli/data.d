build-tsan/src/cli/data.o: src/cli/data.c src/cli/data.h \
 src/cli/options.h src/scene/config.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/scene/measured.h
src/cli/data.h:
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
src/scene/measured.h:
