build-o3/experiments/render.c.o: experiments/render.c core/camera.h \
 core/sampler.h core/rng.h core/scene.h core/vecmath.h core/cli.h \
 core/mlt.h core/image.h core/mlt_stats.h core/pss.h core/parallel.h \
 core/render.h core/util.h build-o3/version.h
core/camera.h:
core/sampler.h:
core/rng.h:
core/scene.h:
core/vecmath.h:
core/cli.h:
core/mlt.h:
core/image.h:
core/mlt_stats.h:
core/pss.h:
core/parallel.h:
core/render.h:
core/util.h:
build-o3/version.h:
