build-tsan/src/tui/replay.o: src/tui/replay.c src/tui/replay.h
src/tui/replay.h:
