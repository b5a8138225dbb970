# libFuzzer targets (tests/fuzz/, tests/README.md "Fuzzing"): clang 14 with libFuzzer, AddressSanitizer
# and UBSan, objects under build-fuzz/. `make fuzz` runs every target FUZZ_S seconds, one after the
# other, and fails on any crash, sanitizer report, leak, timeout (> 1 s per input) or out-of-memory
# (> 512 MB); `make fuzz-build` only builds them. Inputs that failed land in build-fuzz/crash/TARGET/.
FUZZ_S ?= 60
FUZZ_CC := clang-14
FUZZ_BUILD := build-fuzz
FUZZ_TARGETS := scene obj wo3 checkpoint stats_csv texture
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=undefined
FUZZ_CFLAGS := -std=c11 -g -O1 -fno-omit-frame-pointer $(FUZZ_SAN) -fsanitize=fuzzer-no-link $(WARN) -pthread
FUZZ_CPPFLAGS := -Icore -Iexperiments -Itests -I$(BUILD) -D_DEFAULT_SOURCE -MMD -MP
# The core without the OpenImageIO module's loader (main/oiio_stub.c stands in), without MPI and Embree
# (no target casts a ray, main/accel_stub.c stands in for its queries; accel.c's CPU feature names are GCC's); the
# statistics CSV reader of check_stats; the targets and their shared support (the replay suite is
# the test runner's).
FUZZ_SRC := $(filter-out core/io/oiio_load.c core/base/dist_mpi.c core/scene/accel.c,$(wildcard core/*/*.c)) \
  experiments/tools/stats_csv.c tests/fuzz/main/oiio_stub.c tests/fuzz/main/accel_stub.c \
  $(filter-out tests/fuzz/test_%,$(wildcard tests/fuzz/*.c))
FUZZ_OBJ := $(patsubst %,$(FUZZ_BUILD)/%.o,$(FUZZ_SRC))
FUZZ_BINS := $(patsubst %,$(FUZZ_BUILD)/fuzz-%,$(FUZZ_TARGETS))
.PHONY: fuzz fuzz-build fuzz-deps fuzz-seeds
fuzz-deps:
	@bash scripts/install-deps.sh --fuzz

$(FUZZ_BUILD)/%.c.o: %.c | fuzz-deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_BUILD)/entry/%.c.o: tests/fuzz/main/libfuzzer.c | fuzz-deps
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -DFUZZ_ENTRY=fuzz_$* -c $< -o $@

$(FUZZ_BUILD)/libfuzzcore.a: $(FUZZ_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(FUZZ_BUILD)/fuzz-%: $(FUZZ_BUILD)/entry/%.c.o $(FUZZ_BUILD)/libfuzzcore.a
	$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_SAN) -pthread $^ $(CORE_LIBS) -o $@

$(FUZZ_BUILD)/ckpt_seed: tests/fuzz/main/ckpt_seed.c
	@mkdir -p $(dir $@)
	$(CC) -std=c11 -O1 $(WARN) $< -o $@

fuzz-build: $(FUZZ_BINS)

# Seed corpora from the committed scenes, meshes and checkpoints of small renders (seeds.sh).
fuzz-seeds: $(FUZZ_BUILD)/ckpt_seed $(BIN)/render
	bash tests/fuzz/seeds.sh $(FUZZ_BUILD)/seeds $(BIN)/render $(FUZZ_BUILD)/ckpt_seed

# FUZZ_JOBS targets at a time (default 1: the machine's cores may be shared; CI runs 2), each
# libFuzzer process single-threaded; every target runs even after one failed, and the last line
# counts them.
FUZZ_JOBS ?= 1
fuzz: fuzz-build fuzz-seeds
	@mkdir -p $(FUZZ_BUILD)/log; rm -f $(FUZZ_BUILD)/log/*.failed; \
	printf '%s\n' $(FUZZ_TARGETS) | xargs -P $(FUZZ_JOBS) -I{} sh -c \
	  'bash tests/fuzz/run.sh {} $(FUZZ_S) $(FUZZ_BUILD) || touch $(FUZZ_BUILD)/log/{}.failed'; \
	f=$$(ls $(FUZZ_BUILD)/log/*.failed 2>/dev/null | wc -l); n=$(words $(FUZZ_TARGETS)); \
	echo "fuzz: $$((n - f)) passed, $$f failed"; [ $$f -eq 0 ]
-include $(FUZZ_OBJ:.o=.d)
.SECONDARY: $(patsubst %,$(FUZZ_BUILD)/entry/%.c.o,$(FUZZ_TARGETS))
