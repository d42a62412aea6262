build-tsan/src/core/rule_visco.o: src/core/rule_visco.c \
 include/adhere/rule_visco.h include/adhere/drive.h include/adhere/grid.h \
 include/adhere/params.h include/adhere/kernel.h \
 include/adhere/protocol.h include/adhere/run.h include/adhere/observe.h \
 include/adhere/state.h include/adhere/relax.h include/adhere/rule.h \
 include/adhere/visco.h include/adhere/status.h
include/adhere/rule_visco.h:
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
include/adhere/visco.h:
include/adhere/status.h:
