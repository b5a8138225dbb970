# CMLT toy (CMLT paper §5, Table 1 / Figure 3): objects, binary, figure, check and bench targets.
CMLT_OUT := results/table1-cmlt
CMLT_BASE := results/baselines/table1-cmlt
CMLT_COMMIT := $(shell git rev-parse --short HEAD 2>/dev/null || echo unknown)

$(eval $(call TOOLS,cmlt,table1_cmlt))

# tests/cmlt/test_cmlt*.c link the toy's library.
$(BUILD)/tests/cmlt/test_cmlt_check.c.o: CPPFLAGS += -DCHECK_STATS_BIN='"$(BIN)/check_stats"' -DCMLT_BASELINE='"$(CMLT_BASE)/stats-quick.csv"'
TEST_LIBS += $(cmlt_LIB)
$(TEST_BIN): $(BIN)/check_stats

# Table 1 and Figure 3 (the tool writes its own table1.md; its scale comes from SCALE).
table1-cmlt_POST = bash scripts/cmlt-montage.sh $(CMLT_OUT)
$(eval $(call FIGURE,table1-cmlt,table1_cmlt,--commit $(CMLT_COMMIT)))

.PHONY: bench-cmlt

# Statistical regression check: the figure rerun at the current scale (seed 1; the baseline's is
# 1000) into results/check-table1-cmlt/, its RMSE mean and standard error per (algorithm, n) against
# the committed baseline of the same scale (Welch t over seeds, Sidak-corrected alpha = 0.01).
CHECK_table1-cmlt := --key algorithm,n --mean rmse_mean --se rmse_se --count seeds --alpha 0.01
CHECK_table1-cmlt_CSV := table1_stats.csv
# the toy's full scale is the paper's (table1_cmlt --scale full), so is its baseline
CHECK_table1-cmlt_BASE := stats-$(if $(filter full,$(SCALE)),paper,$(SCALE)).csv
CHECK_table1-cmlt_SCALE := $(SCALE)
$(eval $(call CHECK,table1-cmlt,table1_cmlt,1,--commit $(CMLT_COMMIT)))

bench-cmlt: $(BIN)/table1_cmlt
	$(BIN)/table1_cmlt --bench --budgets 4M

BENCH_TARGETS += bench-cmlt
