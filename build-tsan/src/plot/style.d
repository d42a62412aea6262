build-tsan/src/plot/style.o: src/plot/style.c src/plot/plot.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/state.h src/plot/outdir.h \
 src/plot/setup.h src/scene/config.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/scene/measured.h \
 src/scene/datadir.h
src/plot/plot.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
src/plot/outdir.h:
src/plot/setup.h:
src/scene/config.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/relax.h:
include/adhere/rings.h:
include/adhere/units.h:
src/scene/figures.h:
src/scene/measured.h:
src/scene/datadir.h:
