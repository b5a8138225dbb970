build-o3/core/path_walk.c.o: core/path_walk.c core/camera.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/emitter.h \
 core/path.h core/accel.h core/bsdf.h
core/camera.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/emitter.h:
core/path.h:
core/accel.h:
core/bsdf.h:
