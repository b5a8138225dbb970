build-o3/core/mlt.c.o: core/mlt.c core/mlt.h core/image.h core/vecmath.h \
 core/mlt_stats.h core/sampler.h core/rng.h core/pss.h core/scene.h \
 core/connect.h core/path.h core/accel.h core/bsdf.h core/integrator.h \
 core/splat.h core/parallel.h core/util.h
core/mlt.h:
core/image.h:
core/vecmath.h:
core/mlt_stats.h:
core/sampler.h:
core/rng.h:
core/pss.h:
core/scene.h:
core/connect.h:
core/path.h:
core/accel.h:
core/bsdf.h:
core/integrator.h:
core/splat.h:
core/parallel.h:
core/util.h:
