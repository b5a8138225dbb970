build-o3/core/util.c.o: core/util.c core/util.h
core/util.h:
