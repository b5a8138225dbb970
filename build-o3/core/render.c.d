build-o3/core/render.c.o: core/render.c core/render.h core/image.h \
 core/vecmath.h core/scene.h core/integrator.h core/path.h core/accel.h \
 core/bsdf.h core/sampler.h core/rng.h core/splat.h core/parallel.h \
 core/util.h
core/render.h:
core/image.h:
core/vecmath.h:
core/scene.h:
core/integrator.h:
core/path.h:
core/accel.h:
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/splat.h:
core/parallel.h:
core/util.h:
