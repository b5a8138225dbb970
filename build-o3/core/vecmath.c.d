build-o3/core/vecmath.c.o: core/vecmath.c core/vecmath.h
core/vecmath.h:
