# Thesis chapter 6 (equal-time PSSMLT vs MMLT vs PITP), the MMLT paper's §5 ratio and the hybrid-MCTLS
# study: tools, scene assets, figures and tables. Every run goes through bin/render, so a method that
# bin/render accepts (pitp once merged) needs no change here.
CH6_LIB := $(patsubst %,$(BUILD)/%.o,experiments/ch6/ch6_stats.c)
$(BUILD)/experiments/ch6/%: CPPFLAGS += -Iexperiments/ch6
.SECONDARY: $(CH6_LIB) $(BUILD)/experiments/ch6/ch6_assets.c.o $(BUILD)/experiments/ch6/ch6_equal.c.o

$(BIN)/ch6_assets $(BIN)/ch6_equal: $(BIN)/%: $(BUILD)/experiments/ch6/%.c.o $(CH6_LIB) $(LIBCORE) | $(OIIO_MODULE)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@
all: $(BIN)/ch6_assets $(BIN)/ch6_equal

# tests/test_ch6_stats.c sees the analysis code.
$(BUILD)/tests/test_ch6_stats.c.o: CPPFLAGS += -Iexperiments/ch6
TEST_OBJ += $(CH6_LIB)
$(TEST_BIN): $(CH6_LIB)

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
