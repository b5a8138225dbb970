# One entry point: build, test, figures, check, bench. `make help` lists the targets.
# Objects mirror the source tree under build/ (build-san/ for the sanitizer build).

SANITIZE ?= 0
SCALE ?= quick
export SCALE

PGO ?= 1

ifeq ($(SANITIZE),1)
  BUILD := build-san
  BIN := build-san/bin
  OPT := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined
else
  OPT := -O3 -g -fno-math-errno
  # GCC on x86 clears and copies mid-sized structs (a 280-byte path vertex, on every walk) with
  # `rep stos`/`rep movs`, whose start-up costs more than the stores; SSE loops instead: MMLT 2 %,
  # PT 1 %, images bit-identical. Probed, so other compilers and targets build without it.
  OPT += $(shell $(CC) -mstringop-strategy=vector_loop -E -x c /dev/null >/dev/null 2>&1 && echo -mstringop-strategy=vector_loop)
  # Link-time optimisation inlines the small cross-file helpers of the hot paths (edge densities,
  # BSDF dispatch wrappers, ray set-up): 2-5 % on every estimator, images bit-identical.
  # `make clean; make LTO=0` turns it off (objects do not track the flags they were built with).
  ifneq ($(LTO),0)
    OPT += -flto=auto
    AR := gcc-ar
  endif
  # Profile-guided optimisation: bin/render is first built instrumented under build/pgo-gen/ and run
  # on scripts/pgo-train.sh's renders; the release objects are then compiled with those profiles.
  # With -O3, 4-12 % on every estimator (README), images bit-identical (the profile steers inlining,
  # layout and unrolling, never floating-point evaluation). Code the training does not reach is compiled as
  # without a profile (-fprofile-partial-training). `make PGO=0` skips it: faster edit-build cycles.
  # Both stages name a source's profile after the source itself (-dumpbase): GCC keys the
  # profiles of static functions by that name, and would not match them across two object paths.
  PGO_DIR := $(CURDIR)/build/pgo-profile
  PGO_AUX = -dumpdir $(PGO_DIR)/ -dumpbase $(subst /,-,$<)
  ifeq ($(PGO_STAGE),gen)
    BUILD := build/pgo-gen
    BIN := build/pgo-gen/bin
    OPT += -fprofile-generate
    PGO_CFLAGS = $(PGO_AUX)
    # A fixed commit string: a new commit does not make the training stale.
    PGO_COMMIT := pgo-training
  else
    BUILD := build
    BIN := bin
    ifneq ($(PGO),0)
      OPT += -fprofile-use -fprofile-partial-training -Wno-missing-profile
      PGO_CFLAGS = $(PGO_AUX)
      PGO_STAMP := build/pgo.stamp
    endif
  endif
endif

# MPI=1: the renderer over Open MPI ranks (core/base/dist.h, README "MPI: paper-scale runs"). Its objects
# live under $(BUILD)/mpi/; the executables stay in $(BIN), relinked whenever the mode changes
# (LINK_MODE_FILE). The compiler stays the same, Open MPI's flags come from pkg-config (`mpicc` is
# that compiler with those flags), so both modes compile every shared source identically.
MPI ?= 0
LINK_MODE_FILE := $(BUILD)/link-mode
ifeq ($(MPI),1)
  BUILD := $(BUILD)/mpi
  MPI_CFLAGS = $(shell pkg-config --cflags ompi-c)
  MPI_LIBS = $(shell pkg-config --libs ompi-c)
  DIST_SRC_OFF := core/base/dist_single.c
else
  DIST_SRC_OFF := core/base/dist_mpi.c
endif

CC ?= cc
CXX ?= c++
WARN := -Wall -Wextra $(if $(WERROR),-Werror)
# Includes name their folder: "path/path.h" from core/, "common/opts.h" from experiments/.
CPPFLAGS := -Icore -Iexperiments -D_DEFAULT_SOURCE -MMD -MP
CFLAGS := -std=c11 $(OPT) $(WARN) -pthread
# pkg-config is asked when a recipe runs, not when the Makefile is read: on a fresh machine the
# packages (pkg-config among them) arrive only when `deps` runs, after the Makefile was parsed.
OIIO_CFLAGS = $(shell pkg-config --cflags OpenImageIO)
CXXFLAGS = -std=c++17 $(OPT) $(WARN) -pthread -fPIC $(OIIO_CFLAGS)
LDFLAGS := $(OPT) -pthread
# OpenEXR's C core and libpng write the images (core/io/image_encode.h); the fuzz build links the same.
CORE_LIBS := -lembree3 -lcjson -lgsl -lgslcblas -lOpenEXRCore -lpng -lm -ldl
LDLIBS = $(CORE_LIBS) $(MPI_LIBS)
# OpenImageIO lives in a module of its own, opened on the first image read (core/io/oiio.h):
# linked in, Debian's build adds 120 MB and 0.2 s of start-up to every process.
# --no-undefined: a module linked without the library fails here, not at its first use.
OIIO_LIBS = $(shell pkg-config --libs OpenImageIO) -lstdc++ -Wl,--no-undefined

# The commit recorded in every CSV's metadata; version.h is rewritten only when it changes.
GIT_COMMIT := $(or $(PGO_COMMIT),$(shell git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)$(shell git diff --quiet HEAD 2>/dev/null || echo -dirty))
$(shell mkdir -p $(BUILD) && echo '#define GIT_COMMIT "$(GIT_COMMIT)"' > $(BUILD)/version.h.new && (cmp -s $(BUILD)/version.h.new $(BUILD)/version.h || mv $(BUILD)/version.h.new $(BUILD)/version.h))
CPPFLAGS += -I$(BUILD)

CORE_SRC := $(filter-out $(DIST_SRC_OFF),$(wildcard core/*/*.c))
CORE_OBJ := $(patsubst %,$(BUILD)/%.o,$(CORE_SRC))
LIBCORE := $(BUILD)/libcore.a
# A copy beside every directory of executables: core/io/oiio_load.c looks for it there.
OIIO_MODULE := $(BIN)/oiio.so

# Tests mirror the folders they test (tests/mcmc/, tests/ch4/, ...); their shared helpers are in
# tests/support/, included as "support/agree.h"; tests/mpi/ is the MPI runner's own.
TEST_SRC := $(wildcard tests/*/*.c)
TEST_SRC := $(filter-out tests/mpi/%,$(TEST_SRC))
TEST_OBJ := $(patsubst %,$(BUILD)/%.o,$(TEST_SRC))
TEST_BIN := $(BUILD)/tests/run-tests
TEST_OIIO_MODULE := $(BUILD)/tests/oiio.so

# The tools (bin/): every experiments/FOLDER/ lists its mains in its .mk through TOOLS below;
# the folder's other sources become its own library, experiments/common/ is shared by all.
EXP_COMMON_SRC := $(wildcard experiments/common/*.c)
EXP_COMMON_LIB := $(BUILD)/experiments/common/libcommon.a
EXP_SRC := $(EXP_COMMON_SRC)

# $(call TOOLS,FOLDER,NAMES): bin/NAME from experiments/FOLDER/NAME.c, linked with the folder's
# library (its other .c files), experiments/common and the core.
define TOOLS
$(1)_MAINS := $$(patsubst %,experiments/$(1)/%.c,$(2))
$(1)_LIB_SRC := $$(filter-out $$($(1)_MAINS),$$(wildcard experiments/$(1)/*.c))
$(1)_LIB := $$(BUILD)/experiments/$(1)/lib$(1).a
EXP_SRC += $$($(1)_MAINS) $$($(1)_LIB_SRC)
$$($(1)_LIB): $$(patsubst %,$$(BUILD)/%.o,$$($(1)_LIB_SRC))
	@mkdir -p $$(dir $$@) && rm -f $$@
	$$(if $$^,$$(AR) rcs $$@ $$^,printf '!<arch>\n' > $$@)
# Kept after linking: make would otherwise delete them as intermediates of the first build, and
# the next build would recompile and relink (and, with PGO, retrain).
.SECONDARY: $$(patsubst %,$$(BUILD)/%.o,$$($(1)_MAINS) $$($(1)_LIB_SRC))
$$(patsubst %,$$(BIN)/%,$(2)): $$(BIN)/%: $$(BUILD)/experiments/$(1)/%.c.o $$($(1)_LIB) $$($(1)_USES) $$(EXP_COMMON_LIB) $$(LIBCORE) $$(LINK_MODE_FILE) | $$(OIIO_MODULE)
	@mkdir -p $$(dir $$@)
	$$(CC) $$(LDFLAGS) $$(filter %.o %.a,$$^) $$(LDLIBS) -o $$@
tools: $$(patsubst %,$$(BIN)/%,$(2))
endef

.PHONY: all tools deps test test-fast test-san check bench clean help lint golden report figures
SHELL := /bin/bash
all: tools $(LIBCORE) $(TEST_BIN) $(TEST_OIIO_MODULE)
# Every executable of bin/ (experiments in subfolders add theirs in their .mk), without the test runner.
tools: $(OIIO_MODULE)

# Every compile waits for it (order-only), so the first `make` of a fresh machine, with any -j and
# any goal, installs the headers and libraries before it needs them.
# Then the committed full-scale references (results/baselines/reference/, its NOTES.md) go into the
# reference cache where it has none of that name: hours of 2 cores each scene; a key that no longer
# matches the scene or the settings re-renders one, as for any cached reference.
deps:
	@bash scripts/install-deps.sh $(if $(filter 1,$(MPI)),--mpi)
	@for f in results/baselines/reference/*.exr; do [ -e "$$f" ] || continue; n=$${f##*/}; \
	  [ -e results/reference/$$n ] || { mkdir -p results/reference && cp "$$f" "$${f%.exr}.key" results/reference/; }; done

# Which library the executables in $(BIN) were linked against ("mpi" or "plain"), rewritten only
# when it changes: switching MPI=0/1 relinks them from the other mode's objects.
$(LINK_MODE_FILE): FORCE
	@mkdir -p $(dir $@)
	@echo '$(if $(filter 1,$(MPI)),mpi,plain)' > $@.new
	@cmp -s $@.new $@ && rm $@.new || mv $@.new $@

# OpenImageIO's flags as pkg-config gives them now; rewritten only when they change, so the module
# is rebuilt and relinked when the package appears (or moves) after an earlier build.
OIIO_FLAGS_FILE := $(BUILD)/oiio-flags
$(OIIO_FLAGS_FILE): FORCE | deps
	@mkdir -p $(dir $@)
	@echo '$(OIIO_CFLAGS) | $(OIIO_LIBS)' > $@.new
	@cmp -s $@.new $@ && rm $@.new || mv $@.new $@

$(BUILD)/%.c.o: %.c $(PGO_STAMP) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PGO_CFLAGS) -c $< -o $@

# Only the MPI implementation of core/base/dist.h sees Open MPI's headers.
$(BUILD)/core/base/dist_mpi.c.o: CPPFLAGS += $(MPI_CFLAGS)

$(BUILD)/%.cpp.o: %.cpp $(OIIO_FLAGS_FILE) | deps
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# The sub-make brings the instrumented renderer up to date; only when it changed is it retrained
# and the stamp touched, which recompiles every release object against the new profiles. Its own
# BUILD and BIN on its command line: a `make BUILD=DIR` passes DIR down, which would otherwise put
# the instrumented objects where the release ones go.
.PHONY: FORCE
build/pgo.stamp: FORCE | deps
	@$(MAKE) --no-print-directory PGO_STAGE=gen MPI=0 BUILD=build/pgo-gen BIN=build/pgo-gen/bin build/pgo-gen/bin/render
	@if [ ! -e $@ ] || [ build/pgo-gen/bin/render -nt $@ ]; then \
	  set -e; rm -rf $(PGO_DIR); mkdir -p $(PGO_DIR); \
	  echo "training the profile-guided build (scripts/pgo-train.sh)"; \
	  bash scripts/pgo-train.sh build/pgo-gen/bin/render build/pgo-gen/train; \
	  touch $@; fi

$(LIBCORE): $(CORE_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(OIIO_MODULE): $(BUILD)/core/io/oiio.cpp.o $(OIIO_FLAGS_FILE)
	@mkdir -p $(dir $@)
	$(CXX) -shared $(LDFLAGS) $< $(OIIO_LIBS) -o $@

$(TEST_OIIO_MODULE): $(OIIO_MODULE)
	@mkdir -p $(dir $@)
	cp $< $@

$(EXP_COMMON_LIB): $(patsubst %,$(BUILD)/%.o,$(EXP_COMMON_SRC))
	@rm -f $@
	$(AR) rcs $@ $^

# End-to-end tests run the tools of the same build. Test objects are not link-time optimised: LTO
# drops the registration records of Criterion's parameterised tests, and tests gain nothing from it.
$(BUILD)/tests/%.c.o: CPPFLAGS += -Itests -DBIN_DIR='"$(BIN)"'
$(BUILD)/tests/%.c.o: CFLAGS += -fno-lto
$(TEST_BIN): | tools
# TEST_LIBS: the experiments' libraries some tests exercise (added by their .mk files).
$(TEST_BIN): $(TEST_OBJ) $(EXP_COMMON_LIB) $(LIBCORE) | $(TEST_OIIO_MODULE)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $(TEST_OBJ) $(TEST_LIBS) $(EXP_COMMON_LIB) $(LIBCORE) $(LDLIBS) -lcriterion -o $@

# Statistical suites are named stat_*; the fast subset is everything else.
TEST_ARGS ?=
test: deps all
	$(TEST_BIN) --jobs 2 $(TEST_ARGS)

# The MPI suite (tests/mpi/): bin/render under `mpirun -np 2` and `-np 3` on this machine,
# oversubscribed. Built and run in the MPI=1 mode, which leaves bin/'s tools linked against Open MPI
# (a later plain `make` relinks them); the plain test runner is not rebuilt for it. mpirun refuses root unless told (CI runs as root); containers
# without ptrace rights refuse Open MPI's cross-memory copies, hence the copy mechanism `none`.
MPI_TEST_SRC := $(wildcard tests/mpi/*.c)
MPI_TEST_BIN := $(BUILD)/tests/run-mpi-tests
$(MPI_TEST_BIN): CPPFLAGS += -DBIN_DIR='"$(BIN)"'
$(MPI_TEST_BIN): $(patsubst %,$(BUILD)/%.o,$(MPI_TEST_SRC)) $(LIBCORE) | $(TEST_OIIO_MODULE)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $(filter %.o,$^) $(LIBCORE) $(LDLIBS) -lcriterion -o $@
$(BUILD)/tests/mpi/%.c.o: CPPFLAGS += -DBIN_DIR='"$(BIN)"'
$(BUILD)/tests/mpi/%.c.o: CFLAGS += -fno-lto

.PHONY: test-mpi
ifeq ($(MPI),1)
test-mpi: deps tools $(MPI_TEST_BIN)
	OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none \
	  $(MPI_TEST_BIN) --jobs 1 $(TEST_ARGS)
else
test-mpi:
	$(MAKE) MPI=1 test-mpi
endif

test-fast: deps all
	$(TEST_BIN) --jobs 2 --filter '!(stat_*)/*' $(TEST_ARGS)

# AddressSanitizer + UBSan on the fast tests. Criterion reports a leak but still counts the test
# as passed, so the log is searched for sanitizer reports as well. Criterion's own runner leaks 48
# bytes on full runs: tests/lsan.supp says how that is suppressed without hiding the project's leaks.
# intercept_tls_get_addr=0: GCC 12's LeakSanitizer tells glibc's dynamic-TLS blocks apart by their
# alignment and, now and then, mistakes one for an old glibc's layout; the leak check of a process
# that dlopen()ed oiio.so then reads a bogus range and dies ("Tracer caught signal 11 ... does not work
# under ptrace", exit status 1; google/sanitizers#1322). Seen in 1 render of ~250 per run. Static TLS
# and every stack and heap are still scanned.
test-san: deps
	$(MAKE) SANITIZE=1 all
	@set -o pipefail; ASAN_OPTIONS=detect_leaks=1:malloc_context_size=2:intercept_tls_get_addr=0 LSAN_OPTIONS=suppressions=tests/lsan.supp:print_suppressions=0 build-san/tests/run-tests --jobs 2 --filter '!(stat_*)/*' 2>&1 \
	  | tee build-san/test-san.log
	@! grep -q "LeakSanitizer\|runtime error\|AddressSanitizer" build-san/test-san.log \
	  || (echo "sanitizer reports in build-san/test-san.log" >&2; exit 1)

# ---- figures: each writes results/<target>/, its check-<target> compares with results/baselines/ ----
CHECK_STATS := $(BIN)/check_stats

# $(call TO_FILE,FILE,COMMAND): COMMAND's standard output into FILE through a temporary beside it,
# so that FILE is either the old or the complete new one; a failure (a full disk) removes the
# temporary and says so in one line naming FILE (scripts/to-file.sh).
TO_FILE = bash scripts/to-file.sh make $(1) $(2)
# $(call GNUPLOT,SCRIPT,CSV,OUT): OUT.png and OUT.pdf from a gnuplot script, through temporaries
# that a failure removes (scripts/plot.sh).
GNUPLOT = bash scripts/plot.sh $(1) $(2) $(3)

# $(call FIGURE,TARGET,TOOL[,ARGS]): `make TARGET` runs bin/TOOL (with the options ARGS) into
# results/TARGET/ (the tools write every file atomically; the scale comes from SCALE, which the
# tools read), then the lines of TARGET_POST (plots, montages), then, when TARGET_TABLE is set, the
# Markdown table that command prints, into results/TARGET/TARGET.md. Set the variables before the call.
define FIGURE
.PHONY: $(1)
$(1): deps $$(BIN)/$(2)
	$$(BIN)/$(2) --out results/$(1)$(if $(3), $(3))
	$$($(1)_POST)
ifneq ($($(1)_TABLE),)
	$$(call TO_FILE,results/$(1)/$(1).md,$$($(1)_TABLE))
	@cat results/$(1)/$(1).md
endif
FIGURE_TARGETS += $(1)
endef

# $(call CHECK,TARGET,TOOL,SEED[,ARGS]): `make check-TARGET` reruns the quick experiment
# (CHECK_TARGET_SCALE: another scale) with its own seed and the tool options ARGS into
# results/check-TARGET/ (CHECK_TARGET_RUN: another command for that) and tests every statistic of
# its CSV TARGET.csv (CHECK_TARGET_CSV: another name) against the baseline's file of the same name
# (CHECK_TARGET_BASE: another) in results/baselines/TARGET/ with bin/check_stats and the options
# CHECK_TARGET (key, mean, standard error, count and alpha: check_stats --help); the verdicts go to
# check.md. Further comparisons: each name N of CHECK_TARGET_ALSO compares the CSV
# CHECK_TARGET_N_CSV (default TARGET.csv) with the options CHECK_TARGET_N into check-N.md; then all
# comparisons run and any failure fails the check at the end; without CHECK_TARGET, check.md is
# the others' verdicts in alphabetical order of their names. Set the variables before the call.
define CHECK
.PHONY: check-$(1)
check-$(1): deps $$(BIN)/$(2) $$(CHECK_STATS)
	$(or $(CHECK_$(1)_RUN),$$(BIN)/$(2) --scale $(or $(CHECK_$(1)_SCALE),quick) --seed $(3) --out results/check-$(1)$(if $(4), $(4)))
ifeq ($(CHECK_$(1)_ALSO),)
	$$(call CHECK_CMP,$(1),$$(CHECK_$(1)),check.md,$(or $(CHECK_$(1)_CSV),$(1).csv),$(CHECK_$(1)_BASE))
else
	status=0; $$(strip $$(call CHECK_CMPS,$(1))) exit $$$$status
endif
CHECK_TARGETS += check-$(1)
endef
# $(call CHECK_CMP,TARGET,OPTIONS,VERDICTS,CSV[,BASELINE]): one comparison of CHECK (the baseline's
# file named BASELINE, default CSV).
CHECK_CMP = $(CHECK_STATS) $(2) --out results/check-$(1)/$(3) results/baselines/$(1)/$(or $(5),$(4)) results/check-$(1)/$(4)
# Every comparison of TARGET for one shell line, each followed by `|| status=1;`.
CHECK_CMPS = $(if $(CHECK_$(1)),$(call CHECK_CMP,$(1),$(CHECK_$(1)),check.md,$(or $(CHECK_$(1)_CSV),$(1).csv),$(CHECK_$(1)_BASE)) || status=1;) \
  $(foreach n,$(CHECK_$(1)_ALSO),$(call CHECK_CMP,$(1),$(CHECK_$(1)_$(n)),check-$(n).md,$(or $(CHECK_$(1)_$(n)_CSV),$(1).csv)) || status=1;) \
  $(if $(CHECK_$(1)),,cat $(foreach n,$(sort $(CHECK_$(1)_ALSO)),results/check-$(1)/check-$(n).md) > results/check-$(1)/check.md;)

# Experiments in subfolders add their figure, check and bench rules here.
-include experiments/*/*.mk
$(TEST_BIN): $(TEST_LIBS)
# `make fuzz`: the libFuzzer targets of tests/fuzz/ (clang 14, their own build-fuzz/).
include tests/fuzz/fuzz.mk

.PHONY: check
check: $(CHECK_TARGETS)

# The issue targets' figures on the Cornell box, then a table over every committed scene; built
# with MPI=1, also the scaling from one rank to two (bench-mpi).
bench: deps all $(BENCH_TARGETS)
	$(BIN)/bench
	$(BIN)/bench --runs 1 --seconds 1 scenes/*/scene.json
	bash scripts/bench-technique-ir.sh $(BIN)
	$(if $(filter 1,$(MPI)),bash scripts/bench-mpi.sh $(BIN)/render)

# Error x time against Tungsten 0.2.2 per method pair, whole one-thread processes (scripts/bench-tungsten.sh;
# `tungsten` on PATH, ../shared/README.md builds it; SEEDS, SPP, REF_SPP, SCENES, PAIRS from the environment;
# every run in results/bench-tungsten/runs.csv).
.PHONY: bench-tungsten
bench-tungsten: deps $(BIN)/render
	bash scripts/bench-tungsten.sh $(BIN) results/bench-tungsten

# 1 rank x 2 threads against 2 ranks x 1 thread (scripts/bench-mpi.sh), in the MPI=1 build.
.PHONY: bench-mpi
ifeq ($(MPI),1)
bench-mpi: deps $(BIN)/render
	bash scripts/bench-mpi.sh $(BIN)/render
else
bench-mpi:
	$(MAKE) MPI=1 bench-mpi
endif

# ---- make report: one static page with every figure (scripts/report.sh), checked in headless Chromium ----
# Every figure of the report at SCALE, one after the other (each is resumable where its tool is), so
# that `make figures report` gives the whole ledger in one command.
figures:
	@set -e; for t in $(FIGURE_TARGETS); do echo "== make $$t SCALE=$(SCALE)"; $(MAKE) --no-print-directory $$t; done

report:
	@bash scripts/install-deps.sh --report
	REPORT_TARGETS='$(FIGURE_TARGETS)' bash scripts/report.sh $(SCALE)
	bash scripts/report-check.sh results/report/index.html

# ---- make lint: the architecture and the layout, checked. The core's folders include only those
# listed before them (scripts/check-layering.sh reads the order from core/README.md; its own test
# on a tiny tree, tests/tools/check-layering-test.sh, shows it still fails on an upward include),
# and every tracked C/C++ source is as clang-format 14 lays it out (scripts/check-format.sh;
# LINT_FORMAT=list names only the files that differ).
lint:
	@bash scripts/install-deps.sh --lint
	bash scripts/check-layering.sh
	bash tests/tools/check-layering-test.sh
	bash scripts/check-format.sh $(if $(filter list,$(LINT_FORMAT)),--list)

# ---- make golden: every tool's outputs on small, count-budgeted runs (scripts/golden.sh) recorded
# into GOLDEN_DIR, or run again and compared with it: `N same, M differ`, status 1 if any differ.
# Record before a refactor, compare after it.
GOLDEN ?= compare
GOLDEN_DIR ?= results/golden
golden: deps tools
	bash scripts/golden.sh $(GOLDEN) $(BIN) $(GOLDEN_DIR)

clean:
	rm -rf build build-san build-fuzz bin

# The targets are listed once, in README.md's "Make targets" table; `make help` prints that table.
help:
	@awk '/^## Make targets/ { on = 1; next } on && /^## / { exit } \
	  on && /^\| `/ { n = split($$0, c, " \\| "); cmd = c[1]; sub(/^\| /, "", cmd); what = c[2]; \
	    for (i = 3; i < n; i++) what = what " | " c[i]; sub(/ \|$$/, "", what); \
	    gsub(/`/, "", cmd); gsub(/`/, "", what); gsub(/\]\([^)]*\)/, "", what); gsub(/\[/, "", what); \
	    printf "%-28s %s\n", cmd, what }' README.md

# Every object's header dependencies, the experiments' subfolders (ch4/, cmlt/, fig5/, ...) included.
-include $(CORE_OBJ:.o=.d) $(BUILD)/core/io/oiio.cpp.d $(TEST_OBJ:.o=.d) $(patsubst %,$(BUILD)/%.d,$(MPI_TEST_SRC)) $(patsubst %,$(BUILD)/%.d,$(EXP_SRC) $(wildcard experiments/*/*.c))
