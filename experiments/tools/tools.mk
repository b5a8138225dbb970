# The general tools: the renderer, the throughput figures and the baseline checker.
$(eval $(call TOOLS,tools,render bench check_stats))
TEST_LIBS += $(tools_LIB)
