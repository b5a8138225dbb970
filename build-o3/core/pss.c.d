build-o3/core/pss.c.o: core/pss.c core/pss.h core/sampler.h core/rng.h
core/pss.h:
core/sampler.h:
core/rng.h:
