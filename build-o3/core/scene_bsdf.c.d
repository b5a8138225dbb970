build-o3/core/scene_bsdf.c.o: core/scene_bsdf.c core/metals.h \
 core/vecmath.h core/scene_load_internal.h core/json_get.h core/scene.h \
 core/util.h
core/metals.h:
core/vecmath.h:
core/scene_load_internal.h:
core/json_get.h:
core/scene.h:
core/util.h:
