# adhere: build, test, install. `make run` opens the TUI, `make check` runs
# every test; both first install missing Debian packages (as root).
PREFIX  ?= /usr/local
DESTDIR ?=
BINDIR   = $(PREFIX)/bin
DATADIR  = $(PREFIX)/share/adhere
MANDIR   = $(PREFIX)/share/man

CC      ?= cc
CFLAGS  ?= -O2 -g
WARN     = -Wall -Wextra -Wshadow -Wno-unused-parameter -Wno-format-truncation
PKGS     = gsl ncursesw inih openblas
DEBS     = libgsl-dev libncurses-dev libopenblas-dev libinih-dev gnuplot-nox mandoc pkg-config tmux \
           clang libclang-rt-14-dev libhmat-oss-dev

# GSL through OpenBLAS's CBLAS, not the reference gslcblas (DESIGN.md section 4).
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs-only-L gsl 2>/dev/null) -lgsl -lhmat \
             $(shell pkg-config --libs openblas ncursesw inih 2>/dev/null) -lpthread -lm
ADH_VERSION = 0.1.0
CPPFLAGS += -Iinclude -Isrc -DADH_VERSION='"$(ADH_VERSION)"' -D_POSIX_C_SOURCE=200809L -DADH_DATADIR='"$(DATADIR)"' -DADH_SRCDATA='"$(CURDIR)/share/adhere"'
ALL_CFLAGS = -std=c11 $(WARN) $(CFLAGS) $(PKG_CFLAGS)

BUILD   ?= build
LIB_SRC  = $(wildcard src/core/*.c src/scene/*.c src/plot/*.c)
APP_SRC  = $(wildcard src/cli/*.c src/tui/*.c)
LIB_OBJ  = $(LIB_SRC:%.c=$(BUILD)/%.o)
APP_OBJ  = $(APP_SRC:%.c=$(BUILD)/%.o)
LIB      = $(BUILD)/libadhere.a
UNIT_SRC = $(wildcard tests/unit/*.c)
UNIT_BIN = $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
HARD_SRC = $(wildcard tests/hard/*.c)
HARD_BIN = $(HARD_SRC:tests/hard/%.c=$(BUILD)/tests/hard-%)
BENCH_SRC = $(wildcard tests/bench/*.c)
BENCH_BIN = $(BENCH_SRC:tests/bench/%.c=$(BUILD)/tests/bench-%)

.PHONY: all deps run check check-asan check-fuzz asan-build fuzz-build bench install \
        uninstall clean

all: deps adhere

# Installs what is missing and nothing else: a no-op when every package is there.
deps:
	@missing=""; for p in $(DEBS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" != 0 ]; then echo "adhere needs:$$missing (run 'make deps' as root, or apt-get install them)" >&2; exit 1; fi; \
	  echo "installing:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null || exit 1; \
	fi

adhere: $(APP_OBJ) $(LIB)
	$(CC) $(ALL_CFLAGS) -o $@ $(APP_OBJ) $(LIB) $(PKG_LIBS) $(LDFLAGS)

$(LIB): $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

# The data directory is compiled in: a different PREFIX must rebuild, or an
# installed adhere would look for its scenes where they are not.
$(BUILD)/datadir.stamp: FORCE
	@mkdir -p $(BUILD)
	@echo '$(DATADIR)' | cmp -s - $@ || echo '$(DATADIR)' > $@
.PHONY: FORCE
$(LIB_OBJ) $(APP_OBJ): $(BUILD)/datadir.stamp

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/tests/%: tests/unit/%.c tests/unit/tap.h $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/unit $(ALL_CFLAGS) -o $@ $< $(LIB) $(PKG_LIBS)

$(BUILD)/tests/hard-%: tests/hard/%.c tests/unit/tap.h $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Itests/unit $(ALL_CFLAGS) -o $@ $< $(LIB) $(PKG_LIBS)

$(BUILD)/tests/bench-%: tests/bench/%.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -o $@ $< $(LIB) $(PKG_LIBS)

run: all
	./adhere

# One pass, one closing line: the tests, the C tests again under ASan and
# UBSan, and a short fuzz pass over the parsers.
check: all $(UNIT_BIN) $(HARD_BIN) asan-build fuzz-build
	@ASAN_BUILD=build-asan FUZZ_BUILD=$(BUILD) tests/run-all.sh $(BUILD)

SAN_FLAGS = -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined

asan-build: deps
	@$(MAKE) --no-print-directory BUILD=build-asan CFLAGS="$(SAN_FLAGS)" \
	  $(UNIT_SRC:tests/unit/%.c=build-asan/tests/%) $(HARD_SRC:tests/hard/%.c=build-asan/tests/hard-%)

check-asan: asan-build
	@ONLY=c tests/run-all.sh build-asan

# libFuzzer targets, built with clang over the parsers' own sources.
FUZZ_CC    = clang
FUZZ_FLAGS = -g -O1 -fsanitize=fuzzer,address,undefined $(CPPFLAGS) $(PKG_CFLAGS)
FUZZ_BIN   = $(BUILD)/fuzz/fuzz_units $(BUILD)/fuzz/fuzz_scene $(BUILD)/fuzz/fuzz_replay
CORE_SRC   = $(wildcard src/core/*.c)

$(BUILD)/fuzz/fuzz_units: tests/fuzz/fuzz_units.c src/core/units.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ -lm
$(BUILD)/fuzz/fuzz_scene: tests/fuzz/fuzz_scene.c $(wildcard src/scene/*.c) $(CORE_SRC)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ $(PKG_LIBS)
$(BUILD)/fuzz/fuzz_replay: tests/fuzz/fuzz_replay.c src/tui/replay.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ $(PKG_LIBS)

fuzz-build: $(FUZZ_BIN)

check-fuzz: fuzz-build
	@BUILD=$(BUILD) tests/fuzz/run.sh

bench: all $(BENCH_BIN)
	@tests/bench/run.sh $(BUILD)

install: all
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(DATADIR)/scenes $(DESTDIR)$(DATADIR)/gnuplot \
	  $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man5
	install -m 755 adhere $(DESTDIR)$(BINDIR)/adhere
	for f in share/adhere/scenes/*.scene; do [ -e "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(DATADIR)/scenes/; done; true
	for f in share/adhere/gnuplot/*.gp; do [ -e "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(DATADIR)/gnuplot/; done; true
	install -m 644 man/adhere.1 $(DESTDIR)$(MANDIR)/man1/adhere.1
	[ ! -e man/adhere-scene.5 ] || install -m 644 man/adhere-scene.5 $(DESTDIR)$(MANDIR)/man5/adhere-scene.5

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/adhere $(DESTDIR)$(MANDIR)/man1/adhere.1 $(DESTDIR)$(MANDIR)/man5/adhere-scene.5
	rm -rf $(DESTDIR)$(DATADIR)

clean:
	rm -rf $(BUILD) build-asan adhere

-include $(LIB_OBJ:.o=.d) $(APP_OBJ:.o=.d)
