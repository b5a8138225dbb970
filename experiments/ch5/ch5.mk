# Thesis Figures 5.5 and 5.6 (controlled small steps, §5.3) on scenes/jewelry: binaries, figures,
# checks against results/baselines/, montages and tables.
$(eval $(call TOOLS,ch5,fig5_5 fig5_6))

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
