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

.PHONY: check-table1-cmlt bench-cmlt

# Statistical regression check: RMSE mean and standard error per (algorithm, n) against the
# committed baseline of the same scale (Welch z/t test, Sidak-corrected alpha = 0.01).
check-table1-cmlt: table1-cmlt $(BIN)/check_stats
	$(BIN)/check_stats --key algorithm,n --mean rmse_mean --se rmse_se --count seeds --alpha 0.01 \
	  --out $(CMLT_OUT)/check.md $(CMLT_BASE)/stats-$(SCALE).csv $(CMLT_OUT)/table1_stats.csv

bench-cmlt: $(BIN)/table1_cmlt
	$(BIN)/table1_cmlt --bench --budgets 4M

CHECK_TARGETS += check-table1-cmlt
BENCH_TARGETS += bench-cmlt
