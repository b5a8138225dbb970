/* bin/ch6_equal's parts (ch6_equal.c is the orchestration): the settings and measurements of one
 * invocation, shared by the method list (ch6_methods.c), the reference (ch6_reference.c), the runs
 * (ch6_runs.c) and the writers (ch6_write.c, ch6_report.c). */
#ifndef CH6_EQUAL_H
#define CH6_EQUAL_H

#include "ch6/ch6_claims.h"
#include "common/proc.h"
#include "common/run_cache.h"
#include <stdbool.h>

#define CH6_MAX_METHODS 16
#define CH6_MAX_BUDGETS 16
#define CH6_MAX_SEEDS 64
#define CH6_MAX_ARGS 64

struct image;

struct ch6_method {
    char name[64];
    char *argv[CH6_MAX_ARGS]; /* bin/render's method options */
    int argc;
    bool available; /* bin/render accepts them */
};

/* One run's measurements: its seconds and the per-run quantities (ch6_claims.h) */
struct ch6_run {
    double seconds, q[Q_COUNT];
};

struct ch6_equal {
    /* the command line */
    const char *prog, *scene, *out, *name, *refpath, *res, *source, *command, *scale, *insets;
    int res_wh[2];                    /* --resolution parsed (when res is set) */
    const char *study;                /* --study: whose scales, and whose claims (ch6_claims.h) */
    const char *scene_name;           /* the scene's folder: the reference's default name, whatever --name */
    char render[4096], extra_s[1024]; /* render: --render, or "render" (in-process) */
    int seeds, refspp, blk, threads, minlen, spp, first_seed;
    int inset[2][4], ninsets; /* --insets parsed: {x, y, w, h} each; 0 or 2 */
    int named_inset;          /* --named-inset: 1 or 2, the inset the source points at; 0 both */
    int maxlen;               /* --max-length for the reference and every run (0: bin/render's default) */
    char maxlen_s[16];
    double T, ckpt_every;
    bool reuse, wall;
    const char *run_cache_dir; /* --run-cache */
    /* derived */
    struct run_cache cache;    /* runs shared with other studies (common/run_cache.h); dir NULL: off */
    uint64_t scene_hash;       /* ckpt_scene_hash of the scene, for the reference's key and the cache's */
    struct proc_prog renderer; /* how a run executes (common/proc.h) */
    char *extra_argv[CH6_MAX_ARGS], extra_buf[1024];
    int extra_c;
    struct ch6_method ms[CH6_MAX_METHODS];
    int nm, nb;
    double budgets[CH6_MAX_BUDGETS];
    char runsdir[4096], defref[1024], thr[16], minlen_s[16];
    char *methods_buf; /* the --methods text, cut in place into ms[].argv */
    /* the reference: mean luminance, relMSE epsilon, PNG exposure (nan without a reference) */
    struct image *ref;
    double mlum, eps, expo;
    double *blocks; /* the per-block relMSE scratch, cap values */
    int cap;
    bool *glossy; /* the pixels whose first hit is glossy (glossy_mask.h), with a reference; NULL without */
    int nglossy, glossy_w, glossy_h; /* how many, and the mask's size (the camera's at --resolution) */
    /* R[method][budget][seed]; sum[method][q]: mean and se over seeds at the largest budget */
    struct ch6_run (*R)[CH6_MAX_BUDGETS][CH6_MAX_SEEDS];
    double sum[CH6_MAX_METHODS][Q_COUNT][2];
};

struct opts_spec;
/* ch6_scales.c: argv with the rows of the (--study, --scale, scene) options inserted after argv[0]
 * (argv itself when none match; the caller frees another); the options are found by walking argv as
 * opts_parse will. */
char **ch6_with_scale(const struct opts_spec *spec, int *argc, char **argv);
/* ch6_methods.c: the --methods list parsed into e->ms and probed (bin/render M --help), the
 * --render-args split. */
void ch6_methods_parse(struct ch6_equal *e, const char *methods);
/* ch6_reference.c: the scene's content hash (for the reference's and the run cache's keys; the scene
 * is loaded only when either is used), its glossy pixels at the runs' resolution (with a reference),
 * and the run cache opened when --run-cache names one and the runs are in-process. */
void ch6_scene_identity(struct ch6_equal *e);
/* ch6_reference.c: the cached BDPT reference (common/refcache.h) into e->ref (NULL with
 * --reference-spp 0), its statistics, and OUT/reference.png. */
void ch6_reference(struct ch6_equal *e);
/* ch6_runs.c: every run, interleaved (common/runner.h), into e->R. */
void ch6_runs(struct ch6_equal *e);
/* ch6_write.c: OUT/runs.csv, OUT/summary.csv (filling e->sum) and OUT/stats.csv. */
void ch6_write_tables(struct ch6_equal *e);
/* ch6_report.c: OUT/NAME.md (also on stdout) and the claims. */
void ch6_report(const struct ch6_equal *e);

#endif
