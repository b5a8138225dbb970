build-o3/core/mesh_io.c.o: core/mesh_io.c core/mesh_io.h core/vecmath.h \
 core/util.h
core/mesh_io.h:
core/vecmath.h:
core/util.h:
