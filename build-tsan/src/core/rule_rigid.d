build-tsan/src/core/rule_rigid.o: src/core/rule_rigid.c \
 include/adhere/rule_rigid.h include/adhere/params.h \
 include/adhere/protocol.h include/adhere/grid.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/rule.h \
 include/adhere/kernel.h include/adhere/models.h include/adhere/status.h
include/adhere/rule_rigid.h:
include/adhere/params.h:
include/adhere/protocol.h:
include/adhere/grid.h:
include/adhere/run.h:
include/adhere/observe.h:
include/adhere/state.h:
include/adhere/rule.h:
include/adhere/kernel.h:
include/adhere/models.h:
include/adhere/status.h:
