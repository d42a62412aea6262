build-tsan/src/tui/keysrc.o: src/tui/keysrc.c src/tui/keysrc.h \
 src/tui/replay.h
src/tui/keysrc.h:
src/tui/replay.h:
