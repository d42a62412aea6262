build-tsan/src/cli/kcache.o: src/cli/kcache.c src/cli/kcache.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 src/scene/config.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rings.h include/adhere/units.h src/scene/figures.h \
 include/adhere/status.h src/util/ready.h
src/cli/kcache.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
src/scene/config.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
include/adhere/status.h:
src/util/ready.h:
