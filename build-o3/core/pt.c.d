build-o3/core/pt.c.o: core/pt.c core/connect.h core/path.h core/accel.h \
 core/scene.h core/vecmath.h core/bsdf.h core/sampler.h core/rng.h \
 core/integrator.h core/image.h core/splat.h
core/connect.h:
core/path.h:
core/accel.h:
core/scene.h:
core/vecmath.h:
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/integrator.h:
core/image.h:
core/splat.h:
