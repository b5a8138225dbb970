build-o3/core/mis.c.o: core/mis.c core/path.h core/accel.h core/scene.h \
 core/vecmath.h core/bsdf.h core/sampler.h core/rng.h
core/path.h:
core/accel.h:
core/scene.h:
core/vecmath.h:
core/bsdf.h:
core/sampler.h:
core/rng.h:
