build-tsan/src/core/relax.o: src/core/relax.c include/adhere/relax.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 include/adhere/state.h include/adhere/rings.h include/adhere/law.h \
 include/adhere/status.h include/adhere/units.h
include/adhere/relax.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/state.h:
include/adhere/rings.h:
include/adhere/law.h:
include/adhere/status.h:
include/adhere/units.h:
