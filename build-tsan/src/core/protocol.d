build-tsan/src/core/protocol.o: src/core/protocol.c \
 include/adhere/protocol.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/run.h include/adhere/observe.h include/adhere/state.h \
 include/adhere/rings.h include/adhere/models.h include/adhere/status.h \
 include/adhere/units.h
include/adhere/protocol.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/rings.h:
include/adhere/models.h:
include/adhere/status.h:
include/adhere/units.h:
