build-o3/core/microfacet.c.o: core/microfacet.c core/microfacet.h \
 core/scene.h core/vecmath.h core/warp.h
core/microfacet.h:
core/scene.h:
core/vecmath.h:
core/warp.h:
