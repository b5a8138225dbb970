build-o3/core/fresnel.c.o: core/fresnel.c core/fresnel.h core/vecmath.h
core/fresnel.h:
core/vecmath.h:
