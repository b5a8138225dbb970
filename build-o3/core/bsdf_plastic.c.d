build-o3/core/bsdf_plastic.c.o: core/bsdf_plastic.c core/bsdf.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/bsdf_smooth.h \
 core/fresnel.h core/warp.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/bsdf_smooth.h:
core/fresnel.h:
core/warp.h:
