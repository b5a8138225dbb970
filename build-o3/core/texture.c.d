build-o3/core/texture.c.o: core/texture.c core/image.h core/vecmath.h \
 core/scene.h core/util.h
core/image.h:
core/vecmath.h:
core/scene.h:
core/util.h:
