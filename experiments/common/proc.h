/* Running another program of the build (bin/render) as a subprocess, and a render that
 * checkpoints and resumes: how chapter 6's equal-time runs execute (README: execution model). */
#ifndef PROC_H
#define PROC_H

/* Runs argv (NULL-terminated; argv[0] a path) with stdout and stderr into log (NULL: /dev/null);
 * returns its exit status (128 + N when killed by signal N, -1 when it could not be started). */
int proc_run(char *const *argv, const char *log);

/* Runs the bin/render command rv[0..c-1] (rv has room for 5 more entries) writing PREFIX.*, with
 * --checkpoint every `every` seconds (0: none); an earlier interrupted run's PREFIX.ckpt is resumed
 * (--resume), and one the render refuses (exit 2: other options, another build) is set aside with a
 * "PROG: ... starting over" line and the run starts over. A complete run's checkpoint is removed. */
int proc_render_resumable(const char *prog, char **rv, int c, const char *prefix, double every, const char *log);

#endif
