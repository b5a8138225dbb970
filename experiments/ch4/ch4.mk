# Thesis chapter 4, Figures 4.1-4.3 (resolution-aware proposals, constrained discrete choices):
# the tools' shared objects, figure and check targets. Every output is written atomically: the tools
# and ch4-montage.sh through temporary files, the plots and tables here through NAME.tmp and mv.
CH4_BASE := results/baselines
$(eval $(call TOOLS,ch4,fig4_1 fig4_2 fig4_3 fig4_5 fig4_6))

# tests/test_noise_corr.c links the shared analysis code.
TEST_LIBS += $(ch4_LIB)

# Thesis Figure 4.1: isotropic vs resolution-aware small steps on a 16:9 wall; the error's
# correlation lengths along x and y over seeds.
.PHONY: fig4.1 check-fig4.1
fig4.1: deps $(BIN)/fig4_1
	$(BIN)/fig4_1 --out results/fig4.1
	gnuplot -e "csv='results/fig4.1/fig4.1-profiles.csv'; out='results/fig4.1/fig4.1-profiles.tmp'" scripts/fig4.1.gp
	mv -f results/fig4.1/fig4.1-profiles.tmp.png results/fig4.1/fig4.1-profiles.png && mv -f results/fig4.1/fig4.1-profiles.tmp.pdf results/fig4.1/fig4.1-profiles.pdf
	bash scripts/ch4-montage.sh results/fig4.1/fig4.1.png 2 640x360 \
	  results/fig4.1/iso.png "(a) PSSMLT, isotropic small steps" results/fig4.1/rap.png "(b) resolution-aware (--rap)" \
	  results/fig4.1/error-iso.png "(a) error vs reference" results/fig4.1/error-rap.png "(b) error vs reference"
	bash scripts/fig4.1-table.sh results/fig4.1/fig4.1.csv > results/fig4.1/fig4.1.md.tmp && mv -f results/fig4.1/fig4.1.md.tmp results/fig4.1/fig4.1.md
	@echo "results/fig4.1/fig4.1.png: top the renders, bottom their errors (grey = 0); profiles in fig4.1-profiles.png"
	@cat results/fig4.1/fig4.1.md

# Reruns the quick experiment with other seeds (101..108) and compares every (variant, quantity)
# mean with the baseline: Welch t over the seeds, Sidak-corrected alpha = 0.01.
check-fig4.1: deps $(BIN)/fig4_1 $(CHECK_STATS)
	$(BIN)/fig4_1 --scale quick --seed 101 --out results/check-fig4.1
	$(CHECK_STATS) --key variant,quantity --mean mean --se se --count seeds --alpha 0.01 \
	  --out results/check-fig4.1/check.md $(CH4_BASE)/fig4.1/fig4.1.csv results/check-fig4.1/fig4.1.csv
CHECK_TARGETS += check-fig4.1

# Thesis Figure 4.3: a room seen reflected in a window over darkness; BDPT vs PSSMLT vs PSSMLT with
# constrained discrete choices at equal samples per pixel, against a cached BDPT reference.
.PHONY: fig4.3 check-fig4.3
fig4.3: deps $(BIN)/fig4_3
	$(BIN)/fig4_3 --out results/fig4.3
	bash scripts/ch4-montage.sh results/fig4.3/fig4.3.png 2 512x288 \
	  results/fig4.3/reference.png "reference (BDPT)" results/fig4.3/bdpt.png "(a) BDPT" \
	  results/fig4.3/pssmlt.png "(b) PSSMLT" results/fig4.3/pssmlt-cdc.png "(c) PSSMLT, constrained discrete choices"
	bash scripts/fig4.3-table.sh results/fig4.3/fig4.3.csv results/fig4.3/fig4.3-runs.csv > results/fig4.3/fig4.3.md.tmp && mv -f results/fig4.3/fig4.3.md.tmp results/fig4.3/fig4.3.md
	@echo "results/fig4.3/fig4.3.png: top the reference and BDPT, bottom PSSMLT and PSSMLT --cdc (first seed)"
	@cat results/fig4.3/fig4.3.md

# Reruns the quick experiment with other seeds (101..106) and compares relMSE and small-step
# acceptance per method with the baseline (Welch t over seeds, Sidak alpha = 0.01).
check-fig4.3: deps $(BIN)/fig4_3 $(CHECK_STATS)
	$(BIN)/fig4_3 --scale quick --seed 101 --out results/check-fig4.3
	$(CHECK_STATS) --key method,quantity --mean mean --se se --count seeds --alpha 0.01 \
	  --out results/check-fig4.3/check.md $(CH4_BASE)/fig4.3/fig4.3.csv results/check-fig4.3/fig4.3.csv
CHECK_TARGETS += check-fig4.3

# Thesis Figure 4.2: the wall at 1024², 512², 256² and resolution-scaled steps at 256²: correlation
# length in pixels and relMSE at equal mutations per pixel.
.PHONY: fig4.2 check-fig4.2
fig4.2: deps $(BIN)/fig4_2
	$(BIN)/fig4_2 --out results/fig4.2
	gnuplot -e "csv='results/fig4.2/fig4.2.csv'; out='results/fig4.2/fig4.2-plot.tmp'" scripts/fig4.2.gp
	mv -f results/fig4.2/fig4.2-plot.tmp.png results/fig4.2/fig4.2-plot.png && mv -f results/fig4.2/fig4.2-plot.tmp.pdf results/fig4.2/fig4.2-plot.pdf
	bash scripts/ch4-montage.sh results/fig4.2/fig4.2.png 4 384x384 \
	  results/fig4.2/pssmlt-1024.png "(a) 1024x1024 PSSMLT" results/fig4.2/pssmlt-512.png "(b) 512x512 PSSMLT" \
	  results/fig4.2/pssmlt-256.png "(c) 256x256 PSSMLT" results/fig4.2/rap-resolution-256.png "(d) 256x256 resolution-aware"
	bash scripts/fig4.2-table.sh results/fig4.2/fig4.2.csv > results/fig4.2/fig4.2.md.tmp && mv -f results/fig4.2/fig4.2.md.tmp results/fig4.2/fig4.2.md
	@echo "results/fig4.2/fig4.2.png: the four renders (first seed) at one display size; fig4.2-plot.png: lengths and relMSE"
	@cat results/fig4.2/fig4.2.md

# Reruns the quick experiment with other seeds (101..104) and compares every (configuration,
# quantity) mean with the baseline: Welch t over the seeds, Sidak-corrected alpha = 0.01.
check-fig4.2: deps $(BIN)/fig4_2 $(CHECK_STATS)
	$(BIN)/fig4_2 --scale quick --seed 101 --out results/check-fig4.2
	$(CHECK_STATS) --key config,quantity --mean mean --se se --count seeds --alpha 0.01 \
	  --out results/check-fig4.2/check.md $(CH4_BASE)/fig4.2/fig4.2.csv results/check-fig4.2/fig4.2.csv
CHECK_TARGETS += check-fig4.2
