# Thesis chapter 4: Figures 4.1-4.3 (resolution-aware proposals, constrained discrete choices),
# 4.5 and 4.6 (MCTLS): the tools, figure and check targets (FIGURE, CHECK: the top Makefile).
$(eval $(call TOOLS,ch4,fig4_1 fig4_2 fig4_3 fig4_5 fig4_6))

# tests/ch4/test_noise_corr.c links the shared analysis code.
TEST_LIBS += $(ch4_LIB)

# Thesis Figure 4.1: isotropic vs resolution-aware small steps on a 16:9 wall; the error's
# correlation lengths along x and y over seeds.
define fig4.1_POST
$(call GNUPLOT,scripts/fig4.1.gp,results/fig4.1/fig4.1-profiles.csv,results/fig4.1/fig4.1-profiles)
bash scripts/ch4-montage.sh results/fig4.1/fig4.1.png 2 640x360 \
  results/fig4.1/iso.png "(a) PSSMLT, isotropic small steps" results/fig4.1/rap.png "(b) resolution-aware (--rap)" \
  results/fig4.1/error-iso.png "(a) error vs reference" results/fig4.1/error-rap.png "(b) error vs reference"
@echo "results/fig4.1/fig4.1.png: top the renders, bottom their errors (grey = 0); profiles in fig4.1-profiles.png"
endef
fig4.1_TABLE := bash scripts/fig4.1-table.sh results/fig4.1/fig4.1.csv
$(eval $(call FIGURE,fig4.1,fig4_1))
# Other seeds (101..116); every (variant, quantity) mean, l_x / l_y of the claims among them: Welch t over
# the seeds, Sidak alpha = 0.01.
CHECK_fig4.1 := --key variant,quantity --mean mean --se se --count seeds --alpha 0.01
$(eval $(call CHECK,fig4.1,fig4_1,101))

# Thesis Figure 4.2: the wall at 1024², 512², 256² and resolution-scaled steps at 256²: correlation
# length in pixels and relMSE at equal mutations per pixel.
define fig4.2_POST
$(call GNUPLOT,scripts/fig4.2.gp,results/fig4.2/fig4.2.csv,results/fig4.2/fig4.2-plot)
bash scripts/ch4-montage.sh results/fig4.2/fig4.2.png 4 384x384 \
  results/fig4.2/pssmlt-1024.png "(a) 1024x1024 PSSMLT" results/fig4.2/pssmlt-512.png "(b) 512x512 PSSMLT" \
  results/fig4.2/pssmlt-256.png "(c) 256x256 PSSMLT" results/fig4.2/rap-resolution-256.png "(d) 256x256 resolution-aware"
@echo "results/fig4.2/fig4.2.png: the four renders (first seed) at one display size; fig4.2-plot.png: lengths and relMSE"
endef
fig4.2_TABLE := bash scripts/fig4.2-table.sh results/fig4.2/fig4.2.csv
$(eval $(call FIGURE,fig4.2,fig4_2))
# Other seeds (101..104); every (configuration, quantity) mean, the glossy acceptances among them: Welch t
# over the seeds, Sidak alpha = 0.01.
CHECK_fig4.2 := --key config,quantity --mean mean --se se --count seeds --alpha 0.01
$(eval $(call CHECK,fig4.2,fig4_2,101))

# Thesis Figure 4.3: a room seen reflected in a window over darkness; BDPT vs PSSMLT vs PSSMLT with
# constrained discrete choices at equal samples per pixel, against a cached BDPT reference.
define fig4.3_POST
bash scripts/ch4-montage.sh results/fig4.3/fig4.3.png 2 512x288 \
  results/fig4.3/reference.png "reference (BDPT)" results/fig4.3/bdpt.png "(a) BDPT" \
  results/fig4.3/pssmlt.png "(b) PSSMLT" results/fig4.3/pssmlt-cdc.png "(c) PSSMLT, constrained discrete choices"
@echo "results/fig4.3/fig4.3.png: top the reference and BDPT, bottom PSSMLT and PSSMLT --cdc (first seed)"
endef
fig4.3_TABLE := bash scripts/fig4.3-table.sh results/fig4.3/fig4.3.csv results/fig4.3/fig4.3-runs.csv
$(eval $(call FIGURE,fig4.3,fig4_3))
# Other seeds (101..124); relMSE and small-step acceptance per method: Welch t over seeds, Sidak alpha = 0.01.
CHECK_fig4.3 := --key method,quantity --mean mean --se se --count seeds --alpha 0.01
$(eval $(call CHECK,fig4.3,fig4_3,101))

# Thesis Figure 4.5: acceptance of MMLT large steps vs MCTLS per path length (scenes/ajar).
define fig4.5_POST
$(call GNUPLOT,scripts/fig4.5.gp,results/fig4.5/fig4.5.csv,results/fig4.5/fig4.5)
$(call GNUPLOT,scripts/fig4.5-ratio.gp,results/fig4.5/fig4.5-ratios.csv,results/fig4.5/fig4.5-ratio)
endef
fig4.5_TABLE := bash scripts/fig4.5-table.sh results/fig4.5/fig4.5.csv results/fig4.5/fig4.5-ratios.csv results/fig4.5/fig4.5-trials.csv
$(eval $(call FIGURE,fig4.5,fig4_5))
# Its own seed; every (run, length) acceptance of the six runs: z-test with batch-means errors, Sidak
# alpha = 0.01; then, the same way, every (ratio, length) row of fig4.5-ratios.csv, which holds the
# claims' shares of proposals with light (binomial errors) that fig4.5.csv does not, and every
# (length, statistic) row of fig4.5-trials.csv (the prediction from independent trials and its
# factors, jackknife errors).
CHECK_fig4.5 := --key method,length --mean mean_accept --se stderr --alpha 0.01
CHECK_fig4.5_ALSO := ratios trials
CHECK_fig4.5_ratios := --key ratio,length --mean value --se se --alpha 0.01
CHECK_fig4.5_ratios_CSV := fig4.5-ratios.csv
CHECK_fig4.5_trials := --key length,statistic --mean value --se se --alpha 0.01
CHECK_fig4.5_trials_CSV := fig4.5-trials.csv
$(eval $(call CHECK,fig4.5,fig4_5,2))

# Thesis Figure 4.6: equal-time renders, MMLT large steps vs MCTLS vs the hybrid, relMSE vs BDPT, and
# MCTLS and the hybrid at the cost the thesis's ray count assumes (re-evaluating the current state
# every step).
define fig4.6_POST
bash scripts/ch4-montage.sh results/fig4.6/fig4.6.png 2 320x180 \
  results/fig4.6/reference.png "reference (BDPT)" results/fig4.6/mmlt-large.png "MMLT large steps" \
  results/fig4.6/mctls.png "MCTLS" results/fig4.6/hybrid.png "hybrid" \
  results/fig4.6/mctls-recompute.png "MCTLS at the thesis's cost (recomputing)" \
  results/fig4.6/hybrid-recompute.png "hybrid at the thesis's cost"
@echo "results/fig4.6/fig4.6.png: reference (BDPT), MMLT large steps; MCTLS, hybrid; MCTLS and hybrid recomputing"
endef
fig4.6_TABLE := bash scripts/fig4.6-table.sh results/fig4.6/fig4.6.csv
$(eval $(call FIGURE,fig4.6,fig4_6))
# At a fixed 400 000 proposals per run instead of a time budget (nothing depends on the machine),
# 8 seeds (101-108; the baseline's 1-8): relMSE and the large steps' mean acceptance per method,
# Welch t over the seeds, Sidak alpha = 0.01 over the three methods of each.
CHECK_fig4.6 := --key method --mean relmse --se relmse_se --count seeds --alpha 0.01
CHECK_fig4.6_ALSO := acceptance
CHECK_fig4.6_acceptance := --key method --mean acceptance --se acceptance_se --count seeds --alpha 0.01
$(eval $(call CHECK,fig4.6,fig4_6,101,--mutations 400000 --seeds 8 2>/dev/null))
