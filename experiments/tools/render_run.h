/* bin/render as a library call: the figure tools run their renders in-process through it (the
 * experiments' one execution model, experiments/common/README.md), bin/render's main is only it. */
#ifndef RENDER_RUN_H
#define RENDER_RUN_H

/* Does what `bin/render argv[1..argc-1]` does (options: render --help) and returns its exit
 * status: 0 done, 1 failed (one line on stderr), 2 refused (bad scene, or a --resume that does not
 * fit), 130 interrupted with a checkpoint written. A bad option, like --help, exits the process
 * (status 2, or 0): probe options in a child first when that must not end the caller
 * (common/proc.h's proc_fork_call). Re-entrant: every run starts from the defaults, the Embree ISA
 * included; MPI must be joined (base/dist.h) by the caller before the first run. */
int render_run(int argc, char **argv);

#endif
