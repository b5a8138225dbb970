build-o3/core/parallel.c.o: core/parallel.c core/parallel.h core/util.h
core/parallel.h:
core/util.h:
