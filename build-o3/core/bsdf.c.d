build-o3/core/bsdf.c.o: core/bsdf.c core/bsdf.h core/sampler.h core/rng.h \
 core/scene.h core/vecmath.h core/fresnel.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/fresnel.h:
