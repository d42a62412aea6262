build-tsan/src/scene/measured.o: src/scene/measured.c \
 include/adhere/units.h src/scene/measured.h
include/adhere/units.h:
src/scene/measured.h:
