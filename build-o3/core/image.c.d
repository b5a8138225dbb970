build-o3/core/image.c.o: core/image.c core/image.h core/vecmath.h \
 core/oiio.h core/util.h
core/image.h:
core/vecmath.h:
core/oiio.h:
core/util.h:
