build-o3/core/scene_load.c.o: core/scene_load.c core/camera.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h \
 core/scene_load_internal.h core/json_get.h core/util.h
core/camera.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/scene_load_internal.h:
core/json_get.h:
core/util.h:
