# Thesis chapter 6 (equal-time PSSMLT vs MMLT vs PITP), the MMLT paper's §5 ratio and the hybrid-MCTLS
# study: tools, scene assets, figures and tables. Every run is bin/render's command line, run
# in-process (experiments/tools/render_run.h, linked from the tools' library): a method bin/render
# accepts needs no change here.
ch6_USES := $(BUILD)/experiments/tools/libtools.a
$(eval $(call TOOLS,ch6,ch6_assets ch6_equal ch6_tech fig6_1))

# tests/ch6/test_ch6_stats.c links the analysis code.
TEST_LIBS += $(ch6_LIB)

# Thesis Figure 6.1: small-step acceptance per path length, MMLT vs PITP, split by technique change.
fig6.1_POST = $(call GNUPLOT,scripts/fig6.1.gp,results/fig6.1/fig6.1.csv,results/fig6.1/fig6.1)
fig6.1_TABLE := bash scripts/fig6.1-table.sh results/fig6.1/fig6.1.csv
$(eval $(call FIGURE,fig6.1,fig6_1))
# Its own seed; every (method, length, technique changed) acceptance: Welch t over the 4 runs of
# each, Sidak alpha = 0.01.
CHECK_fig6.1 := --key method,length,technique_changed --mean mean_accept --se run_se --count runs --alpha 0.01
$(eval $(call CHECK,fig6.1,fig6_1,2))

# The generated assets are committed (small; the skies stored as half-float EXR by oiiotool);
# `make ch6-assets` regenerates them.
.PHONY: ch6-assets
ch6-assets: deps $(BIN)/ch6_assets
	$(BIN)/ch6_assets --sky results/ch6-sky-lr.exr --sun 0.25,0.55,0.8
	oiiotool results/ch6-sky-lr.exr -d half --compression zip -o scenes/living-room/sky.exr
	$(BIN)/ch6_assets --sky results/ch6-sky-st.exr --sun 0.2,0.9,0.3
	oiiotool results/ch6-sky-st.exr -d half --compression zip -o scenes/staircase/sky.exr
	rm -f results/ch6-sky-lr.exr results/ch6-sky-st.exr
	$(BIN)/ch6_assets --wood scenes/living-room/wood.png
	$(BIN)/ch6_assets --wood scenes/staircase/wood.png

# ---- equal-time figures (thesis Figures 6.2-6.7) ----
# Every setting of a scale (budgets, seeds, shortest path length, reference samples, seed paths,
# checkpoints, each scene's resolution and insets) is bin/ch6_equal's own table
# (experiments/ch6/ch6_scales.c, also in its --help): make passes the scene and --scale only; the
# insets reach scripts/ch6-figure.sh through summary.csv's `# insets` line. Budgets are separate
# runs with one seed each (no snapshots); the BDPT reference is cached in results/reference/
# (common/refcache.h: re-rendered when the scene or the reference's settings change). The method
# list defaults to pssmlt,mmlt,pitp; a method bin/render does not know is skipped and named in the
# table. At full every render checkpoints each minute, so an interrupted `make` continues where it
# stopped.
CH6_METHODS ?= pssmlt,mmlt,pitp
CH6_OUT := results/ch6-$(SCALE)
# Figure targets share identical runs through one cache (common/run_cache.h: keyed by the build,
# the scene's content and the render's options); checks render their own.
CH6_RUN_CACHE := --run-cache results/run-cache
# SEEDS=N: N seeds (at most 64) instead of the scale's, for every bin/ch6_equal target here: an
# undecided row says how many seeds would decide it. With the full scale's checkpoints the runs
# already complete are kept, so a finished run grows by the new seeds only; while SEEDS is given
# the targets always rerun (`make fig6.4 SCALE=full SEEDS=16`).
CH6_SEEDS := $(if $(SEEDS),--seeds $(SEEDS))
CH6_SEEDS_FORCE := $(if $(SEEDS),ch6-seeds-force)
CH6_SEEDS_CMD := $(if $(SEEDS), SEEDS=$(SEEDS))
.PHONY: ch6-seeds-force
# the claims' source and command for claims.csv, which bin/ch6_equal writes with its verdicts
CH6_living-room_ARGS := --source 'thesis Figs. 6.2 and 6.5' --command 'make fig6.2 SCALE=$(SCALE)$(CH6_SEEDS_CMD)'
CH6_staircase_ARGS := --source 'thesis Figs. 6.3 and 6.6' --command 'make fig6.3 SCALE=$(SCALE)$(CH6_SEEDS_CMD)'
CH6_ajar_ARGS := --source 'thesis Figs. 6.4 and 6.7' --command 'make fig6.4 SCALE=$(SCALE)$(CH6_SEEDS_CMD)'

# The tools are order-only: every commit relinks them (version.h), which must not rerun minutes of
# renders; a changed scene does. `make ch6-clean` reruns everything.
$(CH6_OUT)/%/summary.csv: scenes/%/scene.json $(CH6_SEEDS_FORCE) | deps $(BIN)/ch6_equal $(BIN)/render
	$(BIN)/ch6_equal --scene scenes/$*/scene.json --out $(CH6_OUT)/$* --methods $(CH6_METHODS) --scale $(SCALE) $(CH6_$*_ARGS) $(CH6_SEEDS) $(CH6_RUN_CACHE)
	bash scripts/plot.sh scripts/ch6-time.gp $@ $(CH6_OUT)/$*/error-vs-time "name='$*'"

.PHONY: fig6.2 fig6.3 fig6.4 fig6.5 fig6.6 fig6.7 ch6-clean
define CH6_FIG
$(1): deps $(CH6_OUT)/$(2)/summary.csv
	bash scripts/ch6-figure.sh $(3) $(CH6_OUT)/$(2) $(CH6_OUT)/$(2)/$(1).png
	@echo "$(CH6_OUT)/$(2)/$(1).png; table $(CH6_OUT)/$(2)/$(2).md, error vs time $(CH6_OUT)/$(2)/error-vs-time.png"
	@cat $(CH6_OUT)/$(2)/$(2).md $(CH6_OUT)/$(2)/claims.md
FIGURE_TARGETS += $(1)
endef
$(eval $(call CH6_FIG,fig6.2,living-room,insets))
$(eval $(call CH6_FIG,fig6.3,staircase,insets))
$(eval $(call CH6_FIG,fig6.4,ajar,insets))
$(eval $(call CH6_FIG,fig6.5,living-room,full))
$(eval $(call CH6_FIG,fig6.6,staircase,full))
$(eval $(call CH6_FIG,fig6.7,ajar,full))

# make check-fig6.2 … check-fig6.4 (6.5-6.7 are the same runs' full images): the equal-time runs at
# a fixed number of mutations per pixel instead of a time budget, so that nothing depends on the
# machine's speed: 16 mutations per pixel, quick resolution, 8 seeds (101-108; the baseline's 1-8),
# paths of length >= 3, against the cached quick reference. Every statistic of stats.csv (relMSE,
# its normalisation-free and firefly-robust variants, the splotch statistics, the non-zero ratios,
# the seed pass's error) per method: Welch t over the seeds, Sidak alpha = 0.01 over the rows. The
# baselines are `make ch6-baselines`.
CH6_CHECK_OPTS := --spp 16 --seeds 8 --min-length 3 --reference-spp 256 --render-args "--p-large 0.1"
CH6_CHECK_OPTS_fig6.2 := $(CH6_CHECK_OPTS)
CH6_CHECK_OPTS_fig6.3 := $(CH6_CHECK_OPTS)
CH6_CHECK_OPTS_fig6.4 := $(CH6_CHECK_OPTS) --resolution 256x144
# $(call CH6_CHECK,TARGET,SCENE): check-TARGET through the top Makefile's CHECK (bin/ch6_equal with
# the options CH6_CHECK_OPTS_TARGET, seeds from 101; stats.csv), and ch6-baseline-TARGET, the same
# from seed 1 into results/baselines/TARGET/stats.csv (the hybrid study below uses it too)
define CH6_CHECK
CHECK_$(1) := --key scene,method,statistic --count seeds --alpha 0.01
CHECK_$(1)_CSV := stats.csv
CHECK_$(1)_RUN := $$(BIN)/ch6_equal --scene scenes/$(2)/scene.json --out results/check-$(1) --first-seed 101 $$(CH6_CHECK_OPTS_$(1)) >/dev/null
$$(eval $$(call CHECK,$(1),ch6_equal))
.PHONY: ch6-baseline-$(1)
ch6-baseline-$(1): deps $$(BIN)/ch6_equal
	$$(BIN)/ch6_equal --scene scenes/$(2)/scene.json --out results/ch6-baseline/$(1) --first-seed 1 $$(CH6_CHECK_OPTS_$(1)) >/dev/null
	mkdir -p results/baselines/$(1)
	mv results/ch6-baseline/$(1)/stats.csv results/baselines/$(1)/stats.csv
endef
$(eval $(call CH6_CHECK,fig6.2,living-room))
$(eval $(call CH6_CHECK,fig6.3,staircase))
$(eval $(call CH6_CHECK,fig6.4,ajar))
.PHONY: ch6-baselines
ch6-baselines: ch6-baseline-fig6.2 ch6-baseline-fig6.3 ch6-baseline-fig6.4

# Rerun the chapter-6 experiments from scratch (the references stay cached; the run cache goes).
ch6-clean:
	rm -rf $(CH6_OUT) results/mmlt-ratio $(HYB_OUT) results/run-cache

# ---- MMLT paper §5: the fraction of proposals with non-zero contribution, PSSMLT vs MMLT (vs PITP) ----
# Read from the fig6 runs of the three scenes (their render CSVs count every proposal's contribution;
# paths of length >= 3 as in those runs): all proposals and large steps alone, mean +- standard error
# over seeds at the largest budget.
# MMLT paper §5 / Fig. 5: per-technique images of contribution and of sample count for one path
# length, MMLT vs PSSMLT (scripts/ch6-tech.sh, bin/render --technique-images, bin/ch6_tech): ajar at
# 256x144 as fig6.4, length k = 6 (the paper's Fig. 5), paths of length >= 3, p_large = 0.1, 4 seeds
# per method of 8 s each (full: 8 seeds of 60 s, paper: 120 s: the script's own table). Rerun when
# the scene changes, or by make ch6-clean.
TECH_K := 6
TECH_SEEDS := $(if $(filter quick,$(SCALE)),4,8)
TECH_OUT := results/mmlt-ratio/technique-k$(TECH_K)-$(SCALE)
$(TECH_OUT)/tech.md: scenes/ajar/scene.json | deps $(BIN)/render $(BIN)/ch6_tech
	bash scripts/ch6-tech.sh $(BIN) scenes/ajar/scene.json $(TECH_K) $(TECH_SEEDS) $(TECH_OUT) --scale $(SCALE) --resolution 256x144 --min-length 3 --p-large 0.1

# The paper's own setting besides: direct lighting included (paths of length >= 2), on ajar (the
# door scene's counterpart), the three methods at the scale's budget and seeds; no reference (only
# the render CSVs' counts are read: ch6_equal --reference-spp 0). The scales are bin/ch6_equal's
# (--study ratio).
RATIO_OUT := results/mmlt-ratio/$(SCALE)/ajar-direct
$(RATIO_OUT)/summary.csv: scenes/ajar/scene.json $(CH6_SEEDS_FORCE) | deps $(BIN)/ch6_equal $(BIN)/render
	$(BIN)/ch6_equal --scene scenes/ajar/scene.json --name ajar-direct --out $(RATIO_OUT) --min-length 2 --reference-spp 0 \
	  --study ratio --scale $(SCALE) --source 'MMLT paper §5' --command 'make mmlt-ratio SCALE=$(SCALE)$(CH6_SEEDS_CMD)' $(CH6_SEEDS) $(CH6_RUN_CACHE) >/dev/null

# make check-mmlt-ratio: the paper's setting (ajar, paths of length >= 2, no reference) at a fixed
# 16 mutations per pixel at 256x144, seeds 101-108 against the baseline's 1-8: the non-zero
# fractions (per proposal, per connection, large steps) and the seed pass's error per method
# (Welch t over the seeds, Sidak alpha = 0.01 over the 12 rows); `make ch6-baseline-mmlt-ratio`.
CH6_CHECK_OPTS_mmlt-ratio := --study ratio --spp 16 --seeds 8 --min-length 2 --reference-spp 0 --resolution 256x144 \
  --render-args "--p-large 0.1"
$(eval $(call CH6_CHECK,mmlt-ratio,ajar))
ch6-baselines: ch6-baseline-mmlt-ratio

.PHONY: mmlt-ratio
FIGURE_TARGETS += mmlt-ratio
mmlt-ratio: deps $(CH6_OUT)/living-room/summary.csv $(CH6_OUT)/staircase/summary.csv $(CH6_OUT)/ajar/summary.csv $(RATIO_OUT)/summary.csv $(TECH_OUT)/tech.md
	@mkdir -p results/mmlt-ratio
	$(call TO_FILE,results/mmlt-ratio/mmlt-ratio.md,bash scripts/ch6-ratio.sh $(filter %summary.csv,$^))
	@cat results/mmlt-ratio/mmlt-ratio.md $(TECH_OUT)/tech.md
	@echo "per-technique images: $(TECH_OUT)/technique-images.png"

# ---- thesis §4.3 / §7.1: MMLT large steps vs MCTLS vs hybrid, with small steps (p_large = 0.1) ----
# Equal time per run, 8 seeds, on ajar and living-room at 128x72 (all path lengths), against cached
# 256-spp (paper: 16384) BDPT references: bin/ch6_equal's scales (--study hybrid).
HYB_METHODS := mmlt=--method mmlt,mctls=--method mmlt --large-step mctls,hybrid4=--method mmlt --large-step hybrid --hybrid-length 4,hybrid6=--method mmlt --large-step hybrid --hybrid-length 6,hybrid8=--method mmlt --large-step hybrid --hybrid-length 8
HYB_OUT := results/hybrid-study-$(SCALE)

$(HYB_OUT)/%/summary.csv: scenes/%/scene.json $(CH6_SEEDS_FORCE) | deps $(BIN)/ch6_equal $(BIN)/render
	$(BIN)/ch6_equal --scene scenes/$*/scene.json --out $(HYB_OUT)/$* --methods '$(HYB_METHODS)' --study hybrid --scale $(SCALE) \
	  --source 'thesis §4.3, §7.1' --command 'make hybrid-study SCALE=$(SCALE)$(CH6_SEEDS_CMD)' $(CH6_SEEDS) $(CH6_RUN_CACHE)

.PHONY: hybrid-study
FIGURE_TARGETS += hybrid-study
hybrid-study: deps $(HYB_OUT)/ajar/summary.csv $(HYB_OUT)/living-room/summary.csv
	$(call TO_FILE,$(HYB_OUT)/hybrid-study.md,bash scripts/ch6-hybrid.sh $(filter %summary.csv,$^))
	@cat $(HYB_OUT)/hybrid-study.md

# make check-hybrid-study: the five configurations on ajar at 128x72 (all path lengths) at a fixed
# 16 mutations per pixel instead of a time budget, seeds 101-108 against the baseline's 1-8 and the
# cached quick reference; every statistic of stats.csv per configuration (Welch t over the seeds,
# Sidak alpha = 0.01 over the rows). `make ch6-baseline-hybrid-study` rewrites the baseline.
CH6_CHECK_OPTS_hybrid-study := --study hybrid --methods '$(HYB_METHODS)' --spp 16 --seeds 8 --reference-spp 256 --resolution 128x72 \
  --render-args "--p-large 0.1"
$(eval $(call CH6_CHECK,hybrid-study,ajar))
ch6-baselines: ch6-baseline-hybrid-study

# $(call CH6_STUDY,TARGET,STUDY,SCENES): `make TARGET` runs bin/ch6_equal --study STUDY at the
# scale (its settings are ch6_scales.c's) with the methods TARGET_METHODS, the claims' source
# TARGET_SOURCE, on each of SCENES into results/TARGET-SCALE/SCENE/ (checkpointed at full, SEEDS as
# above), and shows each scene's table and claims; `make check-TARGET` reruns the first scene with
# CH6_CHECK_OPTS_TARGET from seed 101 against results/baselines/TARGET/stats.csv (CH6_CHECK).
# Set the variables before the call; TARGET_POST, if set, is a last command of `make TARGET`.
define CH6_STUDY
$(1)_OUT := results/$(1)-$$(SCALE)
$$($(1)_OUT)/%/summary.csv: scenes/%/scene.json $$(CH6_SEEDS_FORCE) | deps $$(BIN)/ch6_equal $$(BIN)/render
	$$(BIN)/ch6_equal --scene scenes/$$*/scene.json --out $$($(1)_OUT)/$$* --methods '$$($(1)_METHODS)' --study $(2) \
	  --scale $$(SCALE) --source '$$($(1)_SOURCE)' --command 'make $(1) SCALE=$$(SCALE)$$(CH6_SEEDS_CMD)' $$(CH6_SEEDS) $$(CH6_RUN_CACHE) >/dev/null
.PHONY: $(1)
FIGURE_TARGETS += $(1)
$(1): deps $$(patsubst %,$$($(1)_OUT)/%/summary.csv,$(3))
	@cat $$(foreach c,$(3),$$($(1)_OUT)/$$(c)/$$(c).md $$($(1)_OUT)/$$(c)/claims.md)
	$$($(1)_POST)
$$(eval $$(call CH6_CHECK,$(1),$$(firstword $(3))))
ch6-baselines: ch6-baseline-$(1)
endef

# ---- MMLT paper §5, Fig. 4: BDPT vs PSSMLT vs MMLT at equal time (claim M-b) ----
# ajar (the door scene's counterpart), paths of 1 to 8 segments (the paper's 8 bounces, direct light
# included), equal CPU time per method (--study mmlt-equal). Each method takes its own options (BDPT
# has no large steps). Beside them MMLT with the power heuristic in its target (claim M-l, the
# paper's §6: no weighting function found beats the balance heuristic). The check: at 16 samples or
# mutations per pixel, 256x144.
mmlt-equal_METHODS := bdpt,pssmlt=--method pssmlt --p-large 0.1,mmlt=--method mmlt --p-large 0.1,mmlt-power=--method mmlt --p-large 0.1 --power-heuristic
mmlt-equal_SOURCE := MMLT paper §5, Fig. 4
CH6_CHECK_OPTS_mmlt-equal := --study mmlt-equal --methods '$(mmlt-equal_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,mmlt-equal,mmlt-equal,ajar))

# ---- MMLT paper Figs. 1, 4 and 6 against Veach's MLT (claims M-a, M-b, M-c) ----
# mmlt-equal's setting (ajar, paths of 1 to 8 segments, equal CPU time per method) with Veach's MLT
# beside BDPT, PSSMLT and MMLT (bin/render --method mlt: the bidirectional mutation and the lens and
# caustic perturbations, core/mcmc/docs/veach.md). The check: at 16 samples or mutations per pixel, 256x144.
mmlt-fig4_METHODS := bdpt,pssmlt=--method pssmlt --p-large 0.1,mlt=--method mlt,mmlt=--method mmlt --p-large 0.1
mmlt-fig4_SOURCE := MMLT paper Figs. 1, 4, 6
CH6_CHECK_OPTS_mmlt-fig4 := --study mmlt-fig4 --methods '$(mmlt-fig4_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,mmlt-fig4,mmlt-fig4,ajar))

# ---- MMLT paper Fig. 9: the diffuse door (claim M-i) ----
# The same on scenes/ajar-diffuse (ajar without glossy materials: its rough surfaces lambert, the specular plastic kept), PSSMLT, MLT and MMLT.
mmlt-fig9_METHODS := pssmlt=--method pssmlt --p-large 0.1,mlt=--method mlt,mmlt=--method mmlt --p-large 0.1
mmlt-fig9_SOURCE := MMLT paper Fig. 9
CH6_CHECK_OPTS_mmlt-fig9 := --study mmlt-fig9 --methods '$(mmlt-fig9_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,mmlt-fig9,mmlt-fig9,ajar-diffuse))

# ---- Veach's perturbations fused into MMLT and PITP through the inverse (Otsu et al. 2017; thesis §7.1) ----
# mmlt-fig4's setting (equal CPU time, paths of 1 to 8 segments) on a door scene (ajar: diffuse and
# glossy paths through a gap) and a caustic one (glass-marble: caustics on diffuse walls): MMLT, PITP,
# Veach's MLT, and MMLT and PITP with the three fused perturbations (bin/render --fused lens+caustic+multichain,
# core/mcmc/docs/fused.md). `make fused` runs both; each has its check at 16 mutations per pixel.
FUSED_METHODS := mmlt=--method mmlt --p-large 0.1,pitp=--method pitp --p-large 0.1,mlt=--method mlt,mmlt-fused=--method mmlt --p-large 0.1 --fused lens+caustic+multichain,pitp-fused=--method pitp --p-large 0.1 --fused lens+caustic+multichain
fused-door_METHODS := $(FUSED_METHODS)
fused-door_SOURCE := Otsu et al. 2017; thesis §7.1
CH6_CHECK_OPTS_fused-door := --study fused-door --methods '$(FUSED_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,fused-door,fused-door,ajar))
fused-caustic_METHODS := $(FUSED_METHODS)
fused-caustic_SOURCE := Otsu et al. 2017; thesis §7.1
CH6_CHECK_OPTS_fused-caustic := --study fused-caustic --methods '$(FUSED_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,fused-caustic,fused-caustic,glass-marble))
.PHONY: fused check-fused
fused: fused-door fused-caustic
check-fused: check-fused-door check-fused-caustic

# ---- thesis Fig. 3.4: BDPT vs path tracing at equal samples (claim T37) ----
# ajar at the scale's samples per pixel, seeds and resolution (--study background).
bdpt-pt_METHODS := pt,bdpt
bdpt-pt_SOURCE := thesis Fig. 3.4
CH6_CHECK_OPTS_bdpt-pt := --study background --methods pt,bdpt --spp 16 --seeds 8 --resolution 128x72 \
  --reference-spp 1024 --render-args ""
$(eval $(call CH6_STUDY,bdpt-pt,background,ajar))

# ---- thesis §4.2: constrained discrete choices on the chapter-6 scenes (claim T11) ----
# PSSMLT with and without --cdc at the equal-time study's settings (--study cdc). The check: ajar at
# 16 mutations per pixel, 256x144, paths of length >= 3.
cdc-ch6_METHODS := pssmlt=--method pssmlt --p-large 0.1,pssmlt-cdc=--method pssmlt --p-large 0.1 --cdc
cdc-ch6_SOURCE := thesis §4.2
CH6_CHECK_OPTS_cdc-ch6 := --study cdc --methods '$(cdc-ch6_METHODS)' --spp 16 --seeds 8 --min-length 3 \
  --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,cdc-ch6,cdc,ajar living-room staircase))

# ---- thesis Fig. 3.3: MIS of path tracing and next-event estimation against each alone (claim T38) ----
# Paths of 2 segments (direct light) on scenes/veach-mis, Veach's plates and lights, at equal
# samples: bin/render's path tracer (the two techniques, balance heuristic), and BDPT's s = 0, t = 3
# (the BSDF-sampled ray hitting a light) and s = 1, t = 2 (a light sample) alone, unweighted.
mis-robust_METHODS := mis=--method pt,bsdf=--method bdpt --technique-s 0 --technique-t 3,nee=--method bdpt --technique-s 1 --technique-t 2
mis-robust_SOURCE := thesis Fig. 3.3
CH6_CHECK_OPTS_mis-robust := --study mis --methods '$(mis-robust_METHODS)' --spp 16 --seeds 8 --resolution 128x96 \
  --min-length 2 --max-length 2 --reference-spp 1024 --render-args ""
$(eval $(call CH6_STUDY,mis-robust,mis,veach-mis))

# ---- MMLT paper §4: the normalisation once or progressively (claim M-j), one chain per length or
# one over all lengths (claim M-k) ----
# MMLT as the paper runs it, with b_k pooled from the seed pass and every large step
# (--progressive-norm), and with one chain over all lengths (--one-chain), at equal CPU time on the
# three chapter-6 scenes (--study mmlt-design: the cdc study's settings) and on ajar with direct
# light. The check: the paper's setting, ajar at 16 mutations per pixel, 256x144, paths of 1 to 8
# segments.
mmlt-design_METHODS := mmlt=--method mmlt --p-large 0.1,mmlt-progressive=--method mmlt --p-large 0.1 --progressive-norm,mmlt-one-chain=--method mmlt --p-large 0.1 --one-chain
mmlt-design_SOURCE := MMLT paper §4
CH6_CHECK_OPTS_mmlt-design := --study mmlt-design --methods '$(mmlt-design_METHODS)' --spp 16 --seeds 8 --min-length 1 \
  --max-length 8 --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,mmlt-design,mmlt-design,ajar living-room staircase))
# The paper's own setting besides (its renders include direct light, so the chapter-6 scenes' rows
# are harness:M-j and harness:M-k): ajar with paths of 1 to 8 segments, mmlt-equal's lengths and
# reference, under the bare IDs.
MD_DIRECT := $(mmlt-design_OUT)/ajar-direct
$(MD_DIRECT)/summary.csv: scenes/ajar/scene.json $(CH6_SEEDS_FORCE) | deps $(BIN)/ch6_equal $(BIN)/render
	$(BIN)/ch6_equal --scene scenes/ajar/scene.json --name ajar-direct --out $(MD_DIRECT) --methods '$(mmlt-design_METHODS)' \
	  --study mmlt-design --min-length 1 --max-length 8 --scale $(SCALE) --source '$(mmlt-design_SOURCE)' \
	  --command 'make mmlt-design SCALE=$(SCALE)$(CH6_SEEDS_CMD)' $(CH6_SEEDS) $(CH6_RUN_CACHE) >/dev/null
mmlt-design: $(MD_DIRECT)/summary.csv
mmlt-design_POST = @cat $(MD_DIRECT)/ajar-direct.md $(MD_DIRECT)/claims.md

# ---- the harness's question: how often should PITP move the technique? (--pitp-rate) ----
# PITP with the technique perturbation before a small step with probability P (1: the thesis's,
# every one; 0: MMLT's small steps; 0.05: Tungsten's reversible-jump rate, see core/mcmc/README.md)
# at equal CPU time on the three chapter-6 scenes, at the equal-time study's settings (--study
# pitp-rate). Beside each scene's table and claims: scripts/ch6-pitp-rate.sh's table of relMSE, its
# firefly-robust variants and the splotch statistics against P with the best P, and a plot per
# scene (scripts/ch6-pitp-rate.gp: pitp-rate.png). The check: ajar at 16 mutations per pixel,
# 256x144, paths of length >= 3.
pitp-rate_METHODS := p0=--method pitp --p-large 0.1 --pitp-rate 0,p0.05=--method pitp --p-large 0.1 --pitp-rate 0.05,p0.1=--method pitp --p-large 0.1 --pitp-rate 0.1,p0.25=--method pitp --p-large 0.1 --pitp-rate 0.25,p0.5=--method pitp --p-large 0.1 --pitp-rate 0.5,p1=--method pitp --p-large 0.1 --pitp-rate 1
pitp-rate_SOURCE := harness: how often should PITP move the technique?
pitp-rate_POST = bash scripts/ch6-pitp-rate.sh $(pitp-rate_OUT) ajar living-room staircase
CH6_CHECK_OPTS_pitp-rate := --study pitp-rate --methods '$(pitp-rate_METHODS)' --spp 16 --seeds 8 --min-length 3 \
  --reference-spp 256 --resolution 256x144 --render-args ""
$(eval $(call CH6_STUDY,pitp-rate,pitp-rate,ajar living-room staircase))
