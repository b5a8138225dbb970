build-o3/core/distrib.c.o: core/distrib.c core/distrib.h core/util.h
core/distrib.h:
core/util.h:
