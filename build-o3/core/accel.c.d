build-o3/core/accel.c.o: core/accel.c core/accel.h core/scene.h \
 core/vecmath.h core/util.h
core/accel.h:
core/scene.h:
core/vecmath.h:
core/util.h:
