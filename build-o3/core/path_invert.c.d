build-o3/core/path_invert.c.o: core/path_invert.c core/camera.h \
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
