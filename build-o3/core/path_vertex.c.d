build-o3/core/path_vertex.c.o: core/path_vertex.c core/accel.h \
 core/scene.h core/vecmath.h core/emitter.h core/sampler.h core/rng.h \
 core/path.h core/bsdf.h
core/accel.h:
core/scene.h:
core/vecmath.h:
core/emitter.h:
core/sampler.h:
core/rng.h:
core/path.h:
core/bsdf.h:
