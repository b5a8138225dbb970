build-o3/core/bsdf_rough_conductor.c.o: core/bsdf_rough_conductor.c \
 core/bsdf.h core/sampler.h core/rng.h core/scene.h core/vecmath.h \
 core/fresnel.h core/microfacet.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/fresnel.h:
core/microfacet.h:
