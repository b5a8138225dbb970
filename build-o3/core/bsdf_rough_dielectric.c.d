build-o3/core/bsdf_rough_dielectric.c.o: core/bsdf_rough_dielectric.c \
 core/bsdf.h core/sampler.h core/rng.h core/scene.h core/vecmath.h \
 core/fresnel.h core/microfacet.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/fresnel.h:
core/microfacet.h:
