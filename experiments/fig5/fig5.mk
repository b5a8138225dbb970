# Thesis Figures 5.5 and 5.6 (controlled small steps, §5.3) on scenes/jewelry: binaries, figures,
# checks against results/baselines/, montages and tables.
FIG5_COMMON := $(patsubst %,$(BUILD)/%.o,experiments/fig5/fig5_common.c experiments/fig5/edge_mask.c)
$(BUILD)/experiments/fig5/%: CPPFLAGS += -Iexperiments/fig5
.SECONDARY: $(FIG5_COMMON) $(BUILD)/experiments/fig5/fig5_5_main.c.o $(BUILD)/experiments/fig5/fig5_6_main.c.o

$(BIN)/fig5_%: $(BUILD)/experiments/fig5/fig5_%_main.c.o $(FIG5_COMMON) $(LIBCORE) $(LINK_MODE_FILE) | $(OIIO_MODULE)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $(filter-out $(LINK_MODE_FILE),$^) $(LDLIBS) -o $@
tools: $(BIN)/fig5_5 $(BIN)/fig5_6

.PHONY: fig5.5 check-fig5.5 fig5.6 check-fig5.6
# Angle-change images (MMLT vs controlled small steps) with the edge/elsewhere table.
fig5.5: deps $(BIN)/fig5_5
	$(BIN)/fig5_5 --out results/fig5.5
	bash scripts/fig5-montage.sh results/fig5.5 mmlt.angle.png "MMLT small steps" controlled.angle.png "controlled small steps" root.angle.png "root only (Alg. 3)" edges.png "edge mask (2 px)"
	bash scripts/fig5-table.sh results/fig5.5/fig5.5.csv > results/fig5.5/fig5.5.md
	@cat results/fig5.5/fig5.5.md

# Rerun with other seeds; every (kind, region) mean against the baseline: Welch t over seeds,
# Sidak-corrected alpha = 0.01.
check-fig5.5: deps $(BIN)/fig5_5 $(CHECK_STATS)
	$(BIN)/fig5_5 --scale quick --seed 101 --out results/check-fig5.5
	$(CHECK_STATS) --key kind,region --mean mean --se stderr --count seeds --alpha 0.01 \
	  --out results/check-fig5.5/check.md results/baselines/fig5.5/fig5.5.csv results/check-fig5.5/fig5.5.csv
CHECK_TARGETS += check-fig5.5

# Rendered images with p_large = 0.01 beside a BDPT reference, relMSE over seeds.
fig5.6: deps $(BIN)/fig5_6
	$(BIN)/fig5_6 --out results/fig5.6
	bash scripts/fig5-montage.sh results/fig5.6 reference.png "BDPT reference" mmlt.png "MMLT small steps" controlled.png "controlled small steps"
	bash scripts/fig5-table.sh results/fig5.6/fig5.6.csv > results/fig5.6/fig5.6.md
	@cat results/fig5.6/fig5.6.md

check-fig5.6: deps $(BIN)/fig5_6 $(CHECK_STATS)
	$(BIN)/fig5_6 --scale quick --seed 101 --out results/check-fig5.6
	$(CHECK_STATS) --key kind --mean relmse --se stderr --count seeds --alpha 0.01 \
	  --out results/check-fig5.6/check.md results/baselines/fig5.6/fig5.6.csv results/check-fig5.6/fig5.6.csv
CHECK_TARGETS += check-fig5.6
