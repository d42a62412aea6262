build-tsan/src/core/runner.o: src/core/runner.c include/adhere/runner.h \
 include/adhere/drive.h include/adhere/grid.h include/adhere/params.h \
 include/adhere/kernel.h include/adhere/protocol.h include/adhere/run.h \
 include/adhere/observe.h include/adhere/state.h include/adhere/relax.h \
 include/adhere/rule.h include/adhere/static.h include/adhere/folds.h \
 include/adhere/rule_static.h include/adhere/status.h
include/adhere/runner.h:
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
include/adhere/static.h:
include/adhere/folds.h:
include/adhere/rule_static.h:
include/adhere/status.h:
