build-o3/core/metals.c.o: core/metals.c core/metals.h core/vecmath.h
core/metals.h:
core/vecmath.h:
