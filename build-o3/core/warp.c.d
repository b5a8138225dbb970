build-o3/core/warp.c.o: core/warp.c core/warp.h core/vecmath.h
core/warp.h:
core/vecmath.h:
