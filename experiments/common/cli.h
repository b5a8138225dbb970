/* Command-line parsing helpers for the tools: every bad value is one error line and exit 2. */
#ifndef CLI_H
#define CLI_H

#include <stdbool.h>
#include <stdint.h>

struct scene;

/* Prints "PROG: message" to stderr and exits with status 2. */
_Noreturn void cli_fail(const char *prog, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
long cli_long(const char *prog, const char *opt, const char *val, long lo, long hi);
double cli_double(const char *prog, const char *opt, const char *val, double lo, double hi);
uint64_t cli_u64(const char *prog, const char *opt, const char *val);
/* Tools that write images call this before their run: a missing OpenImageIO module (core/oiio.h)
 * is reported at once, as "PROG: message" and exit status 1, not after the run. */
void cli_require_image_output(const char *prog);
/* The value after option argv[*i]; fails if missing. */
const char *cli_value(const char *prog, int argc, char **argv, int *i);

/* The options of the acceptance figure tools: --scene, --scale quick|paper (default $SCALE, else
 * quick), --mutations, --max-length (default 12), --seed (default 1), --threads (default: all
 * cores), --out, --help (prints usage). The caller sets scene and out to its defaults first;
 * mutations stays -1 unless given. */
struct cli_figure {
    const char *scene, *scale, *out;
    long mutations;
    int max_length, threads;
    uint64_t seed;
    bool paper;
};
void cli_figure_parse(const char *prog, const char *usage, int argc, char **argv, struct cli_figure *f);
/* The figure's scene (a load error is one line and exit status 2), with its output folder created. */
struct scene *cli_figure_scene(const struct cli_figure *f);

#endif
