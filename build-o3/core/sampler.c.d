build-o3/core/sampler.c.o: core/sampler.c core/sampler.h core/rng.h
core/sampler.h:
core/rng.h:
