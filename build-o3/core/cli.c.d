build-o3/core/cli.c.o: core/cli.c core/cli.h
core/cli.h:
