build-o3/core/bsdf_dielectric.c.o: core/bsdf_dielectric.c core/bsdf.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/bsdf_smooth.h \
 core/fresnel.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/bsdf_smooth.h:
core/fresnel.h:
