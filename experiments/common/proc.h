/* How a figure tool runs a render: in-process through a program's main-like entry (the
 * experiments' execution model, README "Execution model"), or as another program when the user
 * names one (an MPI launcher, another build); and a render that checkpoints and resumes. */
#ifndef PROC_H
#define PROC_H

/* A program's entry with main's contract: argv NULL-terminated, returns the exit status. */
typedef int (*proc_main)(int argc, char **argv);

/* The renderer of a tool's runs: `main` in-process, or (path set) the program at `path`. */
struct proc_prog {
    const char *path;
    proc_main main;
};

/* Runs argv with stdout and stderr into log (NULL: /dev/null) and returns the exit status (128 + N
 * when killed by signal N, -1 when it could not be started). With p->main the call is in-process
 * (argv[0] is only a name); else argv[0] is p->path, executed. */
int proc_run(const struct proc_prog *p, char **argv, const char *log);

/* As proc_run, in a child process also when in-process: for a call that may exit (an option
 * refused, --help), to learn its status without ending the caller. */
int proc_probe(const struct proc_prog *p, char **argv);

/* Runs the render command rv[0..c-1] (rv has room for 5 more entries) writing PREFIX.*, with
 * --checkpoint every `every` seconds (0: none); an earlier interrupted run's PREFIX.ckpt is resumed
 * (--resume), and one the render refuses (exit 2: other options, another build) is set aside with a
 * "PROG: ... starting over" line and the run starts over. A complete run's checkpoint is removed. */
int proc_render_resumable(const char *prog, const struct proc_prog *p, char **rv, int c, const char *prefix,
                          double every, const char *log);

#endif
