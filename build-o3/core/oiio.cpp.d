build-o3/core/oiio.cpp.o: core/oiio.cpp core/oiio.h
core/oiio.h:
