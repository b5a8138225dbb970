build-o3/core/bsdf_lambert.c.o: core/bsdf_lambert.c core/bsdf.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/bsdf_smooth.h \
 core/warp.h
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/bsdf_smooth.h:
core/warp.h:
