build-o3/core/scene.c.o: core/scene.c core/accel.h core/scene.h \
 core/vecmath.h core/bsdf.h core/sampler.h core/rng.h core/emitter.h
core/accel.h:
core/scene.h:
core/vecmath.h:
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/emitter.h:
