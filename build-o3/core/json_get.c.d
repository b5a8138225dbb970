build-o3/core/json_get.c.o: core/json_get.c core/json_get.h \
 core/vecmath.h
core/json_get.h:
core/vecmath.h:
