build-o3/core/scene_prims.c.o: core/scene_prims.c core/mesh_io.h \
 core/vecmath.h core/scene_load_internal.h core/json_get.h core/scene.h \
 core/util.h
core/mesh_io.h:
core/vecmath.h:
core/scene_load_internal.h:
core/json_get.h:
core/scene.h:
core/util.h:
