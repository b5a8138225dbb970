build-o3/core/json_transform.c.o: core/json_transform.c \
 core/scene_load_internal.h core/json_get.h core/vecmath.h core/scene.h
core/scene_load_internal.h:
core/json_get.h:
core/vecmath.h:
core/scene.h:
