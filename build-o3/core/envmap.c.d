build-o3/core/envmap.c.o: core/envmap.c core/emitter.h core/sampler.h \
 core/rng.h core/scene.h core/vecmath.h core/emitter_table.h \
 core/distrib.h core/util.h core/warp.h
core/emitter.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/emitter_table.h:
core/distrib.h:
core/util.h:
core/warp.h:
