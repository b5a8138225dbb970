build-o3/core/mlt_stats.c.o: core/mlt_stats.c core/mlt_stats.h \
 core/sampler.h core/rng.h
core/mlt_stats.h:
core/sampler.h:
core/rng.h:
