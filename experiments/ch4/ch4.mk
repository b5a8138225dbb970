# Thesis chapter 4, Figures 4.1-4.3 (resolution-aware proposals, constrained discrete choices):
# the tools' shared objects, figure and check targets.
CH4_SRC := $(wildcard experiments/ch4/*.c)
CH4_OBJ := $(patsubst %,$(BUILD)/%.o,$(CH4_SRC))
CH4_BASE := results/baselines

$(BUILD)/experiments/fig4_%.c.o: CPPFLAGS += -Iexperiments/ch4
$(BIN)/fig4_1 $(BIN)/fig4_2 $(BIN)/fig4_3: $(BIN)/%: $(BUILD)/experiments/%.c.o $(CH4_OBJ) $(LIBCORE) | $(OIIO_MODULE)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# tests/test_noise_corr.c sees the shared analysis code.
$(BUILD)/tests/test_noise_corr.c.o: CPPFLAGS += -Iexperiments/ch4
TEST_OBJ += $(CH4_OBJ)
$(TEST_BIN): $(CH4_OBJ)

# Thesis Figure 4.1: isotropic vs resolution-aware small steps on a 16:9 wall; the error's
# correlation lengths along x and y over seeds.
.PHONY: fig4.1 check-fig4.1
fig4.1: deps $(BIN)/fig4_1
	$(BIN)/fig4_1 --out results/fig4.1
	gnuplot -e "csv='results/fig4.1/fig4.1-profiles.csv'; out='results/fig4.1/fig4.1-profiles'" scripts/fig4.1.gp
	bash scripts/ch4-montage.sh results/fig4.1/fig4.1.png 2 640x360 \
	  results/fig4.1/iso.png "(a) PSSMLT, isotropic small steps" results/fig4.1/rap.png "(b) resolution-aware (--rap)" \
	  results/fig4.1/error-iso.png "(a) error vs reference" results/fig4.1/error-rap.png "(b) error vs reference"
	bash scripts/fig4.1-table.sh results/fig4.1/fig4.1.csv > results/fig4.1/fig4.1.md
	@echo "results/fig4.1/fig4.1.png: top the renders, bottom their errors (grey = 0); profiles in fig4.1-profiles.png"
	@cat results/fig4.1/fig4.1.md

# Reruns the quick experiment with other seeds (101..108) and compares every (variant, quantity)
# mean with the baseline: Welch t over the seeds, Sidak-corrected alpha = 0.01.
check-fig4.1: deps $(BIN)/fig4_1 $(CHECK_STATS)
	$(BIN)/fig4_1 --scale quick --seed 101 --out results/check-fig4.1
	$(CHECK_STATS) --key variant,quantity --mean mean --se se --count seeds --alpha 0.01 \
	  --out results/check-fig4.1/check.md $(CH4_BASE)/fig4.1/fig4.1.csv results/check-fig4.1/fig4.1.csv
CHECK_TARGETS += check-fig4.1
