/* The tools' command lines: every option is declared once, in a table (struct opt: name, type,
 * bounds, default, help text, destination), and opts_parse reads argv against it, applies the
 * defaults and prints --help from the same table. Every bad argument is one line on stderr,
 * "PROG: --opt: ...", and exit status 2.
 *
 * Shared groups (below): the options several tools take, declared once (OPTS_FIGURE, OPT_SEEDS,
 * OPT_P_LARGE, ...), used in the tools' tables. */
#ifndef OPTS_H
#define OPTS_H

#include "base/parallel.h"   /* cpu_count: --threads' default */
#include "sampler/sampler.h" /* MAX_PATH_LENGTH: --max-length's bound */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

struct scene;
struct opts_figure;

enum opt_type {
    OPT_END = 0, /* ends a table */
    OPT_FLAG,    /* no value: stores .value (1 when 0) into an integer or bool of any size */
    OPT_INT,     /* an integer in [lo, hi], into an integer or enum of any size (.size) */
    OPT_U64,     /* a non-negative integer into a uint64_t; in [lo, hi] when hi > 0 */
    OPT_DOUBLE,  /* a finite number in [lo, hi] */
    OPT_STRING,  /* any string, into a const char * */
    OPT_CHOICE,  /* one of .choices: its index into dst (any integer size), its name into .str */
    OPT_WXH,     /* WxH, W in [lo, hi], H in [lo2, hi2] (the same as W when hi2 is 0), into int[2];
                  * the value as given into .str */
    OPT_CALL,    /* .call parses the value into dst */
    OPT_TEXT,    /* no option: .help is a line of the help text (a heading) */
};

struct opt {
    const char *name; /* "--spp" */
    enum opt_type type;
    void *dst;        /* where the value goes */
    size_t size;      /* sizeof *dst: OPT_FLAG, OPT_INT, OPT_CHOICE */
    const char *arg;  /* the value's name in the help ("N"); choices: a|b|c unless given */
    const char *help; /* one line, wrapped by --help */
    /* Defaults, applied after the arguments to every option not given, through the same checks:
     * def as it would be given; env: an environment variable that replaces def when set and not
     * empty; paper, full: the defaults at --scale paper and --scale full (def is then the quick
     * one; needs spec.fig; a tool none of whose options has a full default refuses --scale full);
     * def_int: an OPT_INT default computed at run time (help states it). No default: dst keeps
     * the value the tool initialised it with. */
    const char *def, *env, *paper, *full;
    int (*def_int)(void);
    double lo, hi, lo2, hi2;
    const char *const *choices; /* OPT_CHOICE, NULL-terminated */
    const char **str;           /* OPT_CHOICE, OPT_WXH: the value as given (optional) */
    long value;                 /* OPT_FLAG */
    /* The error says "--opt: expected EXPECT, got 'VALUE'"; NULL: generated from the type and bounds */
    const char *expect;
    /* OPT_CALL: false with a message (the error line is "PROG: --opt: WHY") on a bad value */
    bool (*call)(const char *value, void *dst, char *why, size_t n);
    int tag; /* the tool's own (bin/render: which methods read the option) */
};

/* .dst and .size of an option's destination */
#define OPT_DST(x) .dst = &(x), .size = sizeof(x)

struct opts_spec {
    const char *prog;
    const char *usage; /* the first line(s) of --help, "usage: ..." */
    const char *about; /* printed after usage (optional) */
    const char *tail;  /* printed after the options (optional) */
    const struct opt *opts;
    /* Arguments that are not options ("-" included): each to positional (NULL: an error) */
    void (*positional)(const char *prog, const char *arg, void *ctx);
    void *ctx;
    /* Where --scale puts quick/paper/full (OPTS_FIGURE): needed by the .paper and .full defaults */
    struct opts_figure *fig;
};

/* Reads argv[1..argc-1] in order: --help or -h prints the help and exits 0 when it is reached
 * (an earlier bad argument exits 2 first); then applies the defaults. */
void opts_parse(const struct opts_spec *s, int argc, char **argv);
/* The table's entry for an option name, or NULL. */
const struct opt *opts_find(const struct opts_spec *s, const char *name);
/* The help text to f. */
void opts_help(const struct opts_spec *s, FILE *f);

/* Prints "PROG: message" to stderr and exits with status 2. */
_Noreturn void opts_fail(const char *prog, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Tools that read images back (cached references, their runs' images) call this before their run: a
 * missing OpenImageIO module (core/io/oiio.h) is reported at once, as "PROG: message" and exit
 * status 1, not after the run. Writing needs no module (io/image_encode.h). */
void opts_require_image_input(const char *prog);

/* ---- shared groups ---------------------------------------------------------------------------- */

/* What every figure tool takes: --scene FILE, --scale quick|paper|full (default $SCALE, else quick),
 * --seed S (default 1), --threads T (default: all cores), --out DIR. */
struct opts_figure {
    const char *prog; /* set by opts_parse: the error lines' name */
    const char *scene, *scale, *out;
    int scale_i;      /* index into opts_scales */
    bool paper, full; /* --scale paper, --scale full */
    uint64_t seed;
    int threads;
};
extern const char *const opts_scales[]; /* quick, paper, full */
/* The shared options; the tool adds .help, .def, .paper where it has its own (as `...`). */
#define OPT_SCENE(d, ...)                                                                                              \
    {                                                                                                                  \
        "--scene", OPT_STRING, OPT_DST(d), .arg = "FILE", __VA_ARGS__                                                  \
    }
#define OPT_SCALE(f)                                                                                                   \
    {                                                                                                                  \
        "--scale", OPT_CHOICE, OPT_DST((f).scale_i), .choices = opts_scales, .str = &(f).scale,                        \
                                                     .help = "budgets and sizes of the run", .def = "quick",           \
                                                     .env = "SCALE"                                                    \
    }
#define OPT_SEED(d, ...)                                                                                               \
    {                                                                                                                  \
        "--seed", OPT_U64, OPT_DST(d), .arg = "S", __VA_ARGS__                                                         \
    }
#define OPT_THREADS(d, ...)                                                                                            \
    {                                                                                                                  \
        "--threads", OPT_INT, OPT_DST(d), .arg = "T", .lo = 1, __VA_ARGS__                                             \
    }
#define OPT_OUT(d, ...)                                                                                                \
    {                                                                                                                  \
        "--out", OPT_STRING, OPT_DST(d), __VA_ARGS__                                                                   \
    }
#define OPTS_FIGURE(f, scene_dflt, out_dflt)                                                                           \
    OPT_SCENE((f).scene, .help = "scene JSON", .def = scene_dflt), OPT_SCALE(f),                                       \
        OPT_SEED((f).seed, .help = "random seed (the first of several)", .def = "1"),                                  \
        OPT_THREADS((f).threads, .hi = 1024, .help = "worker threads (default: all cores)", .def_int = cpu_count),     \
        OPT_OUT((f).out, .arg = "DIR", .help = "output folder", .def = out_dflt)
#define OPT_SEEDS(d, ...)                                                                                              \
    {                                                                                                                  \
        "--seeds", OPT_INT, OPT_DST(d), .arg = "N", .lo = 2, .hi = 1000, __VA_ARGS__                                   \
    }
#define OPT_P_LARGE(d)                                                                                                 \
    {                                                                                                                  \
        "--p-large", OPT_DOUBLE, OPT_DST(d), .arg = "P", .lo = 0, .hi = 1, .help = "large-step probability",           \
                                             .def = "0.1"                                                              \
    }
#define OPT_MAX_LENGTH(d, ...)                                                                                         \
    {                                                                                                                  \
        "--max-length", OPT_INT, OPT_DST(d), .arg = "K", .lo = 1, .hi = MAX_PATH_LENGTH, __VA_ARGS__                   \
    }
#define OPT_MIN_LENGTH(d, ...)                                                                                         \
    {                                                                                                                  \
        "--min-length", OPT_INT, OPT_DST(d), .arg = "K", .lo = 1, __VA_ARGS__                                          \
    }
#define OPT_RESOLUTION(d, ...)                                                                                         \
    {                                                                                                                  \
        "--resolution", OPT_WXH, OPT_DST(d), .arg = "WxH", __VA_ARGS__                                                 \
    }
#define OPT_REFERENCE(d, ...)                                                                                          \
    {                                                                                                                  \
        "--reference", OPT_STRING, OPT_DST(d), .arg = "FILE", __VA_ARGS__                                              \
    }
#define OPT_REFERENCE_SPP(d, ...)                                                                                      \
    {                                                                                                                  \
        "--reference-spp", OPT_INT, OPT_DST(d), .arg = "N", .lo = 1, .hi = 1 << 24, __VA_ARGS__                        \
    }
/* A reference image cached as FILE, rendered with METHOD at N samples per pixel when missing */
#define OPTS_REFERENCE(path, spp, method, path_pattern, quick, paper_)                                                 \
    OPT_REFERENCE(path, .help = "cached " method " reference EXR (default " path_pattern ")"),                         \
        OPT_REFERENCE_SPP(spp, .help = method " samples per pixel of the reference", .def = quick, .paper = paper_)
#define OPT_MUTATIONS(d, ...)                                                                                          \
    {                                                                                                                  \
        "--mutations", OPT_INT, OPT_DST(d), .arg = "N", .lo = 1, .hi = 1L << 40, __VA_ARGS__                           \
    }
#define OPT_MPP(d, ...)                                                                                                \
    {                                                                                                                  \
        "--mpp", OPT_DOUBLE, OPT_DST(d), .arg = "N", __VA_ARGS__                                                       \
    }
#define OPT_HYBRID_LENGTH(d, ...)                                                                                      \
    {                                                                                                                  \
        "--hybrid-length", OPT_INT, OPT_DST(d), .arg = "K", .lo = 1, .hi = MAX_PATH_LENGTH, __VA_ARGS__                \
    }

/* The figure's scene (a load error is one line and exit status 2), with its output folder created
 * (mkdir -p; a folder that cannot be made: "PROG: cannot create DIR: why" and exit status 2). */
struct scene *opts_figure_scene(const struct opts_figure *f);

/* The acceptance figures (fig4_5, fig6_1): OPTS_FIGURE, --mutations N per method over all lengths
 * (defaults mutations_quick and mutations_paper), --max-length K (default 12). Parses argv, then
 * loads the scene and creates the output folder (opts_figure_scene). */
struct opts_accept {
    struct opts_figure fig;
    long mutations;
    int max_length;
};
struct scene *opts_accept_parse(struct opts_accept *a, const char *prog, const char *scene, const char *out,
                                const char *mutations_quick, const char *mutations_paper, int argc, char **argv);

#endif
