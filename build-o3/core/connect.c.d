build-o3/core/connect.c.o: core/connect.c core/connect.h core/path.h \
 core/accel.h core/scene.h core/vecmath.h core/bsdf.h core/sampler.h \
 core/rng.h core/camera.h core/emitter.h
core/connect.h:
core/path.h:
core/accel.h:
core/scene.h:
core/vecmath.h:
core/bsdf.h:
core/sampler.h:
core/rng.h:
core/camera.h:
core/emitter.h:
