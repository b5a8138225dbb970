build-o3/core/rng.c.o: core/rng.c core/rng.h
core/rng.h:
