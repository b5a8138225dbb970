# Thesis Figures 5.5 and 5.6 (controlled small steps, §5.3) on scenes/jewelry: binaries, figures,
# checks against results/baselines/, montages and tables; the inverse-density test of Eq. 5.3.
$(eval $(call TOOLS,ch5,fig5_5 fig5_6 inverse_density))

# Thesis Fig. 5.5: angle-change images (MMLT vs controlled small steps) with the edge/elsewhere table.
fig5.5_POST = bash scripts/fig5-montage.sh results/fig5.5 mmlt.angle.png "MMLT small steps" controlled.angle.png "controlled small steps" root.angle.png "root only (Alg. 3)" edges.png "edge mask (2 px)"
fig5.5_TABLE := bash scripts/fig5-table.sh results/fig5.5/fig5.5.csv
$(eval $(call FIGURE,fig5.5,fig5_5))
# Other seeds; every (kind, region) mean, the ledger's edge / elsewhere ratios among them: Welch t
# over seeds, Sidak alpha = 0.01 over the 12 rows.
CHECK_fig5.5 := --key kind,region --mean mean --se stderr --count seeds --alpha 0.01
$(eval $(call CHECK,fig5.5,fig5_5,101))

# Thesis Fig. 5.6: rendered images with p_large = 0.01 beside a BDPT reference, relMSE over seeds.
fig5.6_POST = bash scripts/fig5-montage.sh results/fig5.6 reference.png "BDPT reference" mmlt.png "MMLT small steps" controlled.png "controlled small steps"
fig5.6_TABLE := bash scripts/fig5-table.sh results/fig5.6/fig5.6.csv
$(eval $(call FIGURE,fig5.6,fig5_6))
# Other seeds; the five ledger statistics per kind (relMSE, error correlation length, share in 8x8
# blobs, and on the rings' pixels the correlation length and the share in 4x4 blobs): Welch t over
# seeds, Sidak alpha = 0.01 over all ten rows (1 - 0.99^(1/5) per statistic, each check_stats call
# Sidak-corrects over its two rows).
CHECK_fig5.6_ALSO := relmse corrlen blur8 glossy_corrlen glossy_blur4
CHECK_fig5.6_relmse := --key kind --mean relmse --se stderr --count seeds --alpha 0.002008
CHECK_fig5.6_corrlen := --key kind --mean corrlen --se corrlen_se --count seeds --alpha 0.002008
CHECK_fig5.6_blur8 := --key kind --mean blur8 --se blur8_se --count seeds --alpha 0.002008
CHECK_fig5.6_glossy_corrlen := --key kind --mean glossy_corrlen --se glossy_corrlen_se --count seeds --alpha 0.002008
CHECK_fig5.6_glossy_blur4 := --key kind --mean glossy_blur4 --se glossy_blur4_se --count seeds --alpha 0.002008
$(eval $(call CHECK,fig5.6,fig5_6,101))

# Thesis §5.1 Eq. 5.3 (claim T21): the inverted numbers of every sampling function with an inverse
# against its forward numbers (chi-square and KS, Sidak alpha = 0.01 over the functions).
$(eval $(call FIGURE,inverse-density,inverse_density))
# The check is the verdict itself at the quick scale with other seeds: every p-value above the
# corrected level (bin/inverse_density --require-holds exits 1 otherwise); no baseline.
.PHONY: check-inverse-density
check-inverse-density: deps $(BIN)/inverse_density
	$(BIN)/inverse_density --scale quick --seed 101 --out results/check-inverse-density --require-holds
CHECK_TARGETS += check-inverse-density
TEST_LIBS += $(ch5_LIB)
