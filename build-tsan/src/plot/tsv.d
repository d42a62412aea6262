build-tsan/src/plot/tsv.o: src/plot/tsv.c src/plot/tsv.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/state.h src/plot/outdir.h \
 src/plot/setup.h src/scene/config.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/relax.h include/adhere/rings.h \
 include/adhere/units.h src/scene/figures.h src/scene/measured.h \
 include/adhere/models.h src/plot/speed.h
src/plot/tsv.h:
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
include/adhere/models.h:
src/plot/speed.h:
