# adhere: build, test, install. `make run` opens the TUI, `make check` runs
# every test; both first install missing Debian packages (as root): `deps` is
# an order-only prerequisite of every object and test program, so even under
# `make -j8` nothing compiles before the packages are there.
PREFIX  ?= /usr/local
DESTDIR ?=
BINDIR   = $(PREFIX)/bin
DATADIR  = $(PREFIX)/share/adhere
MANDIR   = $(PREFIX)/share/man

CC      ?= cc
CFLAGS  ?= -O2 -g
WARN     = -Wall -Wextra -Wshadow -Wno-unused-parameter -Wformat-truncation=2
PKGS     = gsl ncursesw inih openblas
DEBS     = libgsl-dev libncurses-dev libopenblas-dev libinih-dev gnuplot-nox mandoc pkg-config tmux \
           liblapack-dev libblas-dev liblapacke-dev \
           clang libclang-rt-14-dev libhmat-oss-dev locales libsundials-dev parallel

# GSL through OpenBLAS's CBLAS and LAPACK (dgetrf), not the reference
# gslcblas: several times faster on the dense kernel products and LU that
# dominate the run time. BLAS_LIBS swaps the BLAS (make check-fp does).
# LAPACK is called through lapacke's header (-llapacke); its dgetrf is
# still the one BLAS_LIBS brings, which the program loads first.
# Recursive (=) on purpose: pkg-config runs when a recipe needs it, after
# `deps` has installed it.
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
BLAS_LIBS  = $(shell pkg-config --libs openblas 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs-only-L gsl 2>/dev/null) -lgsl -lhmat -llapacke -lsundials_idas $(BLAS_LIBS) \
             $(shell pkg-config --libs ncursesw inih 2>/dev/null) -lpthread -lm
ADH_VERSION = 0.1.0
CPPFLAGS += -Iinclude -Isrc -DADH_VERSION='"$(ADH_VERSION)"' -D_POSIX_C_SOURCE=200809L -DADH_DATADIR='"$(DATADIR)"'
# -fopenmp-simd: `#pragma omp simd` vectorizes the relaxation's per-node
# passes (no OpenMP runtime, no threads).
ALL_CFLAGS = -std=c11 -fopenmp-simd $(WARN) $(CFLAGS) $(PKG_CFLAGS)
# Test programs sit in $(BUILD)/tests, with no share/adhere beside them: they
# read this tree's (tests/unit/tap.h), unless $$ADHERE_DATADIR says otherwise.
TEST_CPPFLAGS = -Itests/unit -DADH_TEST_DATADIR='"$(CURDIR)/share/adhere"'

BUILD   ?= build
BIN     ?= adhere
# Three archives, layered: libadhere.a is the core alone (physics, no I/O);
# scene files and configuration, and the plots, are their own. LIBS lists
# them in link order (plot uses scene, scene uses the core).
CORE_OBJ  = $(patsubst %.c,$(BUILD)/%.o,$(wildcard src/core/*.c))
SCENE_OBJ = $(patsubst %.c,$(BUILD)/%.o,$(wildcard src/scene/*.c))
PLOT_OBJ  = $(patsubst %.c,$(BUILD)/%.o,$(wildcard src/plot/*.c))
LIB_OBJ  = $(CORE_OBJ) $(SCENE_OBJ) $(PLOT_OBJ)
# The drivers (cli, tui) and their small shared helpers (util: the test
# readiness signal) link into the program.
APP_SRC  = $(wildcard src/cli/*.c src/tui/*.c src/util/*.c)
APP_OBJ  = $(APP_SRC:%.c=$(BUILD)/%.o)
LIB      = $(BUILD)/libadhere.a
SCENE_LIB = $(BUILD)/libadhere-scene.a
PLOT_LIB  = $(BUILD)/libadhere-plot.a
LIBS     = $(PLOT_LIB) $(SCENE_LIB) $(LIB)
UNIT_SRC = $(wildcard tests/unit/*.c)
UNIT_BIN = $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
HARD_SRC = $(wildcard tests/hard/*.c)
HARD_BIN = $(HARD_SRC:tests/hard/%.c=$(BUILD)/tests/hard-%)
BENCH_SRC = $(wildcard tests/bench/*.c)
BENCH_BIN = $(BENCH_SRC:tests/bench/%.c=$(BUILD)/tests/bench-%)

.PHONY: all deps run check check-asan check-fp check-fuzz check-slurm check-tsan deps-slurm asan-build fuzz-build bench install \
        uninstall clean

all: deps $(BIN)

# Installs what of the packages $(1) is missing and nothing else: a no-op
# when every package is there.
define install_debs
	@missing=""; for p in $(1); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" != 0 ]; then echo "adhere needs:$$missing (run 'make $@' as root, or apt-get install them)" >&2; exit 1; fi; \
	  echo "installing:$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null || exit 1; \
	fi
endef

deps:
	$(call install_debs,$(DEBS))

# Slurm and munge for make check-slurm alone (no other target needs them).
SLURM_DEBS = slurm-wlm munge
deps-slurm:
	$(call install_debs,$(SLURM_DEBS))

$(BIN): $(APP_OBJ) $(LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -o $@ $(APP_OBJ) $(LIBS) $(PKG_LIBS) $(LDFLAGS)

$(LIB): $(CORE_OBJ)
	@rm -f $@
	ar rcs $@ $^
$(SCENE_LIB): $(SCENE_OBJ)
	@rm -f $@
	ar rcs $@ $^
$(PLOT_LIB): $(PLOT_OBJ)
	@rm -f $@
	ar rcs $@ $^

# The data directory is compiled in: a different PREFIX must rebuild, or an
# installed adhere would look for its scenes where they are not.
$(BUILD)/datadir.stamp: FORCE
	@mkdir -p $(BUILD)
	@echo '$(DATADIR)' | cmp -s - $@ || echo '$(DATADIR)' > $@
.PHONY: FORCE
$(LIB_OBJ) $(APP_OBJ): $(BUILD)/datadir.stamp

# The installed style is compiled in as the figures' defaults (png.c): one
# palette, whether or not a style file is found. Comments ("# " after a
# blank) and blank lines go; colours ("#CC6677") stay.
$(BUILD)/gen/style.inc: share/adhere/gnuplot/style.gp
	@mkdir -p $(dir $@)
	sed -e '/^#/d' -e 's/  *# .*$$//' -e '/^ *$$/d' -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/.*/"&",/' $< >$@
$(BUILD)/src/plot/png.o: $(BUILD)/gen/style.inc
$(BUILD)/src/plot/png.o: CPPFLAGS += -I$(BUILD)/gen

# The numerics id (study.tsv's numerics line): a hash of every source that
# decides a study's numbers -- the core, the configuration that sets a
# run's grid and the study's runs, the CLI files that step a study's
# drives and fill its rows -- so that a study resumes, and adhere merge
# joins shards, only with rows of the same numerics; a build that changes
# the plots, the TUI or the other messages keeps it. sha256sum over the
# files (not git: a tarball builds it alike), written only when it changes.
NUMERICS_SRC = $(sort $(wildcard src/core/*.[ch] include/adhere/*.h src/scene/*.[ch] \
               $(addprefix src/cli/,studyrow.[ch] jumps.[ch] tables.[ch] timerun.[ch] static.[ch] sweep.c kcache.[ch])))
$(BUILD)/gen/numerics.h: FORCE
	@mkdir -p $(dir $@)
	@line="#define ADH_NUMERICS \"$$(sha256sum $(NUMERICS_SRC) | sha256sum | cut -c1-16)\""; \
	  echo "$$line" | cmp -s - $@ || echo "$$line" >$@
$(BUILD)/src/cli/study.o: $(BUILD)/gen/numerics.h
$(BUILD)/src/cli/study.o: CPPFLAGS += -I$(BUILD)/gen

$(BUILD)/%.o: %.c | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP -c -o $@ $<

# a test that compiles a source of the library with a bound of its own
$(BUILD)/tests/test_path_ubound: src/core/rule_path.c
$(BUILD)/tests/test_forcebase_oom: src/plot/forcebase.c
$(BUILD)/tests/test_static_start_oom: src/core/static.c
$(BUILD)/tests/test_say: src/plot/say.c
# ... or a driver's (the screen's session, its kernel count read)
$(BUILD)/tests/test_tui_start_kernels: src/tui/sim.c src/tui/sim.h
# ... or the CLI's words (its advice, tables and fit report)
$(BUILD)/tests/test_reason_words: src/cli/advice.c src/cli/tables.c src/cli/fitreport.c

# The test programs (some 100 in make check, two builds) link through gold,
# which binutils ships: 0.05 CPU s a program against ld.bfd's 0.18
# (docs/testing.md). Where the compiler cannot use it, its default linker.
TEST_LD := $(shell $(CC) -fuse-ld=gold -Wl,--version 2>/dev/null | grep -q gold && echo -fuse-ld=gold)
# The test programs' own sources at -O0, in both builds (the library they
# link keeps its -O2, or the ASan build's -O1): they compile in half the
# CPU (11.4 -> 6.2 s plain, 14.5 -> 10.2 s under ASan) and run as fast,
# their time being the library's (docs/testing.md). Those above that
# compile a source of the program themselves compile it at -O0 too.
TEST_OPT = -O0

$(BUILD)/tests/%: tests/unit/%.c tests/unit/tap.h $(wildcard tests/unit/*.h) $(LIBS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(TEST_CPPFLAGS) $(ALL_CFLAGS) $(TEST_OPT) $(TEST_LD) -o $@ $< $(LIBS) $(PKG_LIBS)

$(BUILD)/tests/hard-%: tests/hard/%.c tests/unit/tap.h $(LIBS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(TEST_CPPFLAGS) $(ALL_CFLAGS) $(TEST_OPT) $(TEST_LD) -o $@ $< $(LIBS) $(PKG_LIBS)

$(BUILD)/tests/bench-%: tests/bench/%.c $(LIBS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) $(TEST_LD) -o $@ $< $(LIBS) $(PKG_LIBS)

run: all
	./$(BIN)

# One pass, one closing line: the tests, the C tests again under ASan and
# UBSan, a short fuzz pass over the parsers and each benchmark once at a tiny
# size. About 3 minutes from a fresh clone on 2 cores (docs/testing.md). CI=true: a skip fails it.
check: all $(UNIT_BIN) $(HARD_BIN) $(BENCH_BIN) asan-build fuzz-build
	@ADHERE_BIN=$(abspath $(BIN)) ASAN_TESTS="$(ASAN_CHECK)" FUZZ_BUILD=$(BUILD) tests/run-all.sh $(BUILD)

# The replay goldens must hold on any floating-point path, not one machine's:
# the program built again against the reference BLAS (GSL's gslcblas for
# CBLAS, Netlib's LAPACK and BLAS beneath dgetrf, pinned by rpath so the
# system's OpenBLAS alternative cannot stand in) and again at -O0, each in its
# own build dir, and the replay suite run against each. Not part of `check`.
REF_BLAS_DIR  = /usr/lib/x86_64-linux-gnu
REF_BLAS_LIBS = -lgslcblas -L$(REF_BLAS_DIR)/lapack -L$(REF_BLAS_DIR)/blas -llapack -lblas \
                -Wl,--disable-new-dtags,-rpath,$(REF_BLAS_DIR)/lapack:$(REF_BLAS_DIR)/blas
check-fp: deps
	@$(MAKE) --no-print-directory BUILD=build-refblas BIN=build-refblas/adhere \
	  BLAS_LIBS="$(REF_BLAS_LIBS)" build-refblas/adhere
	@$(MAKE) --no-print-directory BUILD=build-O0 BIN=build-O0/adhere CFLAGS="-O0 -g" build-O0/adhere
	@fail=0; for b in build-refblas build-O0; do \
	  if ldd $$b/adhere | grep -q openblas && [ $$b = build-refblas ]; then \
	    echo "not ok - $$b/adhere still loads OpenBLAS"; fail=1; fi; \
	  echo "# replay suite with $$b/adhere"; \
	  ADHERE_BIN=$$PWD/$$b/adhere ADHERE_DATADIR=$$PWD/share/adhere tests/replay/run.sh >$$b/replay.log 2>&1 || fail=1; \
	  grep '^not ok' $$b/replay.log; \
	  echo "$$b: $$(grep -c '^ok' $$b/replay.log) passed, $$(grep -c '^not ok' $$b/replay.log) failed (log: $$b/replay.log)"; \
	done; exit $$fail

# -g1: line tables alone, which is all a sanitizer's report prints (file and
# line of every frame, inlined ones too); full -g cost 9 of this build's 44
# CPU s (docs/testing.md). For a debugger, set SAN_FLAGS with -g.
SAN_FLAGS = -O1 -g1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined

# make check's ASan pass leaves these C tests to its plain build: every
# line and branch of the library they run (gcov over src/), the pass's
# other tests run too (but for two branches that touch no memory,
# docs/testing.md names them), and none is an error path's or an
# allocation's test; make check-asan runs them.
ASAN_PLAIN_ONLY = test_physics test_rate_grid test_soft_static test_static_vs_relax test_visco_converge \
                  test_visco_energy test_visco_limits test_visco_spring
ASAN_ALL   = $(UNIT_SRC:tests/unit/%.c=build-asan/tests/%) $(HARD_SRC:tests/hard/%.c=build-asan/tests/hard-%)
ASAN_CHECK = $(filter-out $(ASAN_PLAIN_ONLY:%=build-asan/tests/%),$(ASAN_ALL))
asan-build: deps
	@$(MAKE) --no-print-directory BUILD=build-asan CFLAGS="$(SAN_FLAGS)" $(ASAN_CHECK)

# Every case of every C test under the sanitizers (TAP_FULL: make check's
# ASan pass leaves a few heavy ones to its plain build, tests/unit/tap.h).
check-asan: asan-build
	@$(MAKE) --no-print-directory BUILD=build-asan CFLAGS="$(SAN_FLAGS)" $(ASAN_ALL)
	@ONLY=c TAP_FULL=1 tests/run-all.sh build-asan

# The two drivers that run on threads (--cost's grid, a study's runs), built
# under ThreadSanitizer and run small on 2 threads: a race stops them.
check-tsan: deps
	@$(MAKE) --no-print-directory BUILD=build-tsan BIN=build-tsan/adhere CFLAGS="-O1 -g -fsanitize=thread" \
	  LDFLAGS="-fsanitize=thread" build-tsan/adhere
	@d=$$(mktemp -d) && export TSAN_OPTIONS=halt_on_error=1 && \
	  build-tsan/adhere --cost --cost-nodes=100,200 --cost-eps=10pm,5pm --turn=-2nm -E 3GPa --no-plot -q -o $$d/cost >$$d/out 2>$$d/err && \
	  build-tsan/adhere --batch -N 100 --force --eps=10pm --no-plot -q tests/cli/map.scene -o $$d/map 2>>$$d/err; \
	  rc=$$?; [ $$rc -eq 0 ] || cat $$d/err; rm -rf $$d; [ $$rc -eq 0 ] && echo "check-tsan: --cost and a 16-run study on 2 threads, no race"; exit $$rc

# libFuzzer targets, built with clang over the parsers' own sources (-g1:
# line tables for the crash's stack, as SAN_FLAGS).
FUZZ_CC    = clang
FUZZ_FLAGS = -g1 -O1 -fsanitize=fuzzer,address,undefined $(CPPFLAGS) $(PKG_CFLAGS)
FUZZ_BIN   = $(BUILD)/fuzz/fuzz_units $(BUILD)/fuzz/fuzz_scene $(BUILD)/fuzz/fuzz_replay \
             $(BUILD)/fuzz/fuzz_gpstring $(BUILD)/fuzz/fuzz_measured
CORE_SRC   = $(wildcard src/core/*.c)

# Each source compiled once into its own object, so that make -j spreads the
# fuzzers' build over the cores (one clang call over every core source was
# a 20 s serial tail of a fresh clone's make check).
FUZZ_OBJ = $(BUILD)/fuzz/obj
$(FUZZ_OBJ)/%.o: %.c | deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -MMD -MP -c -o $@ $<
fuzz_objs = $(patsubst %.c,$(FUZZ_OBJ)/%.o,$(1))
# The scene fuzzers link the whole core, but a parser runs only the few
# sources below (libFuzzer's -print_coverage=1 over the corpus): those are
# compiled here, with the fuzzer's coverage. The rest, numerics no fuzzer
# reaches, come from the ASan/UBSan build's archives (gcc, -O1,
# sanitizers on; clang's runtime serves gcc's instrumentation alike),
# which make check builds anyway: compiling them again with clang, even at
# -O0, was 7 of the fuzzers' 15 CPU s of compiling (docs/testing.md).
# The archives' units.o and the others compiled here are never pulled in:
# the fuzzer's own objects, linked first, define their symbols.
# Of the scene layer, the fuzzers compile what the linker takes for them
# (-Wl,-Map: the plan, its time and budget and the start check are never
# linked in); anything else comes from the ASan build's scene archive.
FUZZ_RUN_CORE = $(addprefix src/core/,units.c params.c protocol.c grid.c rings.c kernel.c relax.c visco_params.c)
FUZZ_SCENE = $(addprefix src/scene/,config.c configset.c datadir.c hint.c origin.c scene.c sweep.c text.c timespec.c)
FUZZ_MEASURED = $(addprefix src/scene/,fitdata.c measured.c text.c)
ASAN_LIBS = build-asan/libadhere-scene.a build-asan/libadhere.a
# asan-build's sub-make builds them (where they are $(LIBS), under their
# own rules); a phony prerequisite, so the scene fuzzers relink (0.3 s
# each) after it, never against a stale archive.
ifneq ($(BUILD),build-asan)
$(ASAN_LIBS): asan-build ;
endif

$(BUILD)/fuzz/fuzz_units: $(call fuzz_objs,tests/fuzz/fuzz_units.c src/core/units.c)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ -lm
$(BUILD)/fuzz/fuzz_scene: $(call fuzz_objs,tests/fuzz/fuzz_scene.c $(FUZZ_SCENE) $(FUZZ_RUN_CORE)) $(ASAN_LIBS)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ $(PKG_LIBS)
$(BUILD)/fuzz/fuzz_measured: $(call fuzz_objs,tests/fuzz/fuzz_measured.c $(FUZZ_MEASURED) $(FUZZ_RUN_CORE)) $(ASAN_LIBS)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ $(PKG_LIBS)
$(BUILD)/fuzz/fuzz_replay: $(call fuzz_objs,tests/fuzz/fuzz_replay.c src/tui/replay.c)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^ $(PKG_LIBS)
$(BUILD)/fuzz/fuzz_gpstring: $(call fuzz_objs,tests/fuzz/fuzz_gpstring.c src/plot/labels.c)
	$(FUZZ_CC) $(FUZZ_FLAGS) -o $@ $^

fuzz-build: $(FUZZ_BIN)

check-fuzz: fuzz-build
	@BUILD=$(BUILD) FUZZ_SECONDS=$${FUZZ_SECONDS:-60} tests/fuzz/run.sh

bench: all $(BENCH_BIN)
	@tests/bench/run.sh $(BUILD)

# The Slurm example (share/adhere/examples) on a single-node Slurm this
# target starts and stops (as root; installs slurm-wlm and munge, which
# nothing else needs). About 10 s; not in `check` (docs/studies.md).
check-slurm: all deps-slurm
	@ADHERE_BIN=$(abspath $(BIN)) tests/slurm/check.sh

install: all
	install -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(DATADIR)/scenes $(DESTDIR)$(DATADIR)/gnuplot $(DESTDIR)$(DATADIR)/data \
	  $(DESTDIR)$(DATADIR)/examples $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(MANDIR)/man5
	install -m 755 $(BIN) $(DESTDIR)$(BINDIR)/adhere
	for f in share/adhere/scenes/*.scene; do [ -e "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(DATADIR)/scenes/; done; true
	for f in share/adhere/gnuplot/*.gp; do [ -e "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(DATADIR)/gnuplot/; done; true
	for f in share/adhere/data/*.tsv; do [ -e "$$f" ] && install -m 644 "$$f" $(DESTDIR)$(DATADIR)/data/; done; true
	install -m 755 share/adhere/examples/study.sbatch share/adhere/examples/merge.sbatch \
	  share/adhere/examples/submit.sh $(DESTDIR)$(DATADIR)/examples/
	install -m 644 man/adhere.1 $(DESTDIR)$(MANDIR)/man1/adhere.1
	[ ! -e man/adhere-scene.5 ] || install -m 644 man/adhere-scene.5 $(DESTDIR)$(MANDIR)/man5/adhere-scene.5

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/adhere $(DESTDIR)$(MANDIR)/man1/adhere.1 $(DESTDIR)$(MANDIR)/man5/adhere-scene.5
	rm -rf $(DESTDIR)$(DATADIR)

clean:
	rm -rf $(BUILD) build-asan build-refblas build-O0 adhere

-include $(LIB_OBJ:.o=.d) $(APP_OBJ:.o=.d) $(wildcard $(FUZZ_OBJ)/*/*.d $(FUZZ_OBJ)/*/*/*.d)
