build-o3/core/bsdf_mirror.c.o: core/bsdf_mirror.c core/bsdf.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/bsdf_smooth.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/bsdf_smooth.h:
