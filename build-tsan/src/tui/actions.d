build-tsan/src/tui/actions.o: src/tui/actions.c src/tui/actions.h \
 src/tui/replay.h
src/tui/actions.h:
src/tui/replay.h:
