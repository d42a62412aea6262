build-tsan/src/scene/datadir.o: src/scene/datadir.c src/scene/datadir.h
src/scene/datadir.h:
