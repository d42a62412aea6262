build-tsan/src/core/drive.o: src/core/drive.c include/adhere/drive.h \
 include/adhere/grid.h include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/clock.h include/adhere/rings.h include/adhere/status.h \
 include/adhere/units.h
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
include/adhere/clock.h:
include/adhere/rings.h:
include/adhere/status.h:
include/adhere/units.h:
