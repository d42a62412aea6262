build-tsan/src/cli/advice.o: src/cli/advice.c src/cli/advice.h \
 include/adhere/status.h
src/cli/advice.h:
include/adhere/status.h:
