build-o3/core/camera.c.o: core/camera.c core/camera.h core/sampler.h \
 core/rng.h core/scene.h core/vecmath.h
core/camera.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
