build-o3/core/camera_setup.c.o: core/camera_setup.c core/camera.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h
core/camera.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
