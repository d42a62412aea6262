build-tsan/src/core/visco.o: src/core/visco.c src/core/visco.h \
 include/adhere/visco.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h src/core/visco_pre.h \
 include/adhere/clock.h include/adhere/models.h include/adhere/rings.h \
 include/adhere/status.h
src/core/visco.h:
include/adhere/visco.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/kernel.h:
include/adhere/protocol.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
src/core/visco_pre.h:
include/adhere/clock.h:
include/adhere/models.h:
include/adhere/rings.h:
include/adhere/status.h:
