build-tsan/src/core/observe.o: src/core/observe.c \
 include/adhere/observe.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/state.h include/adhere/law.h include/adhere/models.h \
 include/adhere/rings.h
include/adhere/observe.h:
include/adhere/grid.h:
include/adhere/params.h:
include/adhere/state.h:
include/adhere/law.h:
include/adhere/models.h:
include/adhere/rings.h:
