/* The table of struct mlt_opts's options (mlt_options.h) and what is derived from it: defaults,
 * the checkpoint identity, the CSV lines' order and values, and the checks between options. */
#include "mcmc/mlt_options.h"
#include "base/dist.h"
#include "mcmc/mctls.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const mlt_option_methods[] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp", "mlt", NULL};

unsigned mlt_method_bit(const char *method)
{
    for (int i = 0; mlt_option_methods[i]; i++)
        if (!strcmp(method, mlt_option_methods[i])) return 1u << i;
    return 0;
}

unsigned mlt_method_mask(enum mlt_method m)
{
    return m == MLT_PSSMLT ? APPLIES_PSSMLT
           : m == MLT_MMLT ? APPLIES_MMLT
           : m == MLT_PITP ? APPLIES_PITP
                           : APPLIES_VEACH;
}

/* ---- the checks between options (mlt_render's; the messages name what each needs) ---- */

static bool small_step_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    /* the reverse density needs the Gaussian's (controlled_step.h); MCTLS does not keep the
     * current subpaths; --cdc would make the kernel singular */
    if (o->method != MLT_PSSMLT && o->large_step == LARGE_MMLT && o->pss.kernel == KERNEL_GAUSSIAN && !o->pss.cdc)
        return false;
    snprintf(err, errlen,
             "controlled and root small steps need mmlt or pitp, MMLT large steps, the Gaussian kernel and no --cdc");
    return true;
}

static bool power_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    /* PITP picks a technique in proportion to the balance heuristic's weights (Eq. 5.22-5.25) and
     * MCTLS sums the techniques' balance-weighted contributions (Eq. 4.7): another heuristic is MMLT's
     * target with its own large steps only */
    if (o->method == MLT_MMLT && o->large_step == LARGE_MMLT) return false;
    snprintf(err, errlen, "--power-heuristic: mmlt with MMLT large steps only");
    return true;
}

static bool technique_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    if (o->method == MLT_PITP || o->large_step != LARGE_MMLT || o->technique_k < o->min_length ||
        o->technique_k > o->max_length) {
        snprintf(err, errlen,
                 "technique images need pssmlt or mmlt with MMLT large steps and a length within "
                 "--min-length..--max-length");
        return true;
    }
    if (dist_size() > 1) {
        snprintf(err, errlen, "technique images are not merged across MPI ranks: make them without mpirun");
        return true;
    }
    return false;
}

static bool mctls_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    /* Eq. 4.7's sums do not change by a zero term: counting t = 0 needs drawn trials */
    if (o->method != MLT_PSSMLT && o->large_step != LARGE_MMLT && o->mctls_tries >= (o->mctls_count_t0 ? 1 : 0) &&
        o->mctls_tries <= MCTLS_MAX_TRIES)
        return false;
    snprintf(err, errlen, "MCTLS trials: 1..%d, with mmlt or pitp and MCTLS large steps; counting t = 0 needs them",
             MCTLS_MAX_TRIES);
    return true;
}

static bool veach_mix_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    if (o->veach_lens + o->veach_caustic + o->veach_lens_subpath + o->veach_multichain <= 1) return false;
    snprintf(err, errlen,
             "--mlt-lens, --mlt-caustic, --mlt-lens-subpath and --mlt-multichain: their sum is the shares of the "
             "mutations other than the bidirectional one, at most 1");
    return true;
}

/* the fused perturbations' lines only in the runs that make them: the others' CSVs keep theirs */
static bool fused_on(const struct mlt_opts *o) { return o->fused != FUSED_NONE; }
static bool large_step_mis_on(const struct mlt_opts *o) { return o->large_step_mis; }

static bool progressive_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    /* the rescale is per length: a chain that changes its length has no length's image to rescale */
    if (!o->one_chain) return false;
    snprintf(err, errlen, "--progressive-norm rescales each length's chain: not with --one-chain");
    return true;
}

static bool one_chain_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    /* the length changes only in a large step of fresh numbers (one_chain.c); MCTLS's trials, the
     * controlled steps' kept subpaths and the technique images are per length */
    if (o->method == MLT_MMLT && o->large_step == LARGE_MMLT && o->small_step == SMALL_STEP_PSS && !o->technique_k)
        return false;
    snprintf(err, errlen, "--one-chain: mmlt with MMLT large steps, the pss small step and no technique images");
    return true;
}

static bool angle_conflict(const struct mlt_opts *o, char *err, size_t errlen)
{
    if (o->method != MLT_PSSMLT && o->large_step == LARGE_MMLT) return false;
    snprintf(err, errlen, "angle statistics need mmlt or pitp with MMLT large steps");
    return true;
}

/* ---- the table ---- */

#define FIELD(f) .offset = offsetof(struct mlt_opts, f), .size = sizeof(((struct mlt_opts *)0)->f), .field = #f

static const char *const kernels[] = {"kelemen", "gaussian", NULL};
static const char *const large_steps[] = {"mmlt", "mctls", "hybrid", NULL};
static const char *const small_steps[] = {"pss", "controlled", "root", NULL};
static const char *const seed_estimators[] = {"pool", "bdpt"};
static const char *const mis_names[] = {"balance", "maximum"};
static const char *const normalisations[] = {"seed", "progressive"};
static const char *const chain_layouts[] = {"per_length", "one"};
/* indexed by the set's bits (enum fused_moves) */
static const char *const fused_moves[] = {"none",
                                          "lens",
                                          "caustic",
                                          "lens+caustic",
                                          "multichain",
                                          "lens+multichain",
                                          "caustic+multichain",
                                          "lens+caustic+multichain",
                                          NULL};

const struct mlt_option mlt_options[] = {
    /* bin/render's, in its --help order */
    {"p_large", "--p-large", MLT_OPTION_DOUBLE, FIELD(p_large), .def = "0.1", .lo = 0, .hi = 1, .arg = "P",
     .methods = APPLIES_MCMC, .numbers = true, .help = "large-step probability", .csv_group = MLT_CSV_AFTER_COUNTS,
     .csv_pos = 1, .csv_key = "p_large"},
    {"kernel", "--kernel", MLT_OPTION_CHOICE, FIELD(pss.kernel), .choices = kernels, .methods = APPLIES_MCMC,
     .numbers = true, .help = "small-step kernel (default kelemen: s1 = 1/1024, s2 = 1/64)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 2, .csv_key = "kernel"},
    {"sigma", "--sigma", MLT_OPTION_DOUBLE, FIELD(pss.sigma), .lo = 1e-9, .hi = 1, .arg = "S", .methods = APPLIES_MCMC,
     .numbers = true, .help = "gaussian small-step standard deviation (default 1/64)",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 7, .csv_key = "sigma"},
    {"rap", "--rap", MLT_OPTION_FLAG, FIELD(pss.rap), .methods = APPLIES_MCMC, .numbers = true,
     .help = "resolution-aware proposals: image steps corrected for aspect ratio", .csv_group = MLT_CSV_AFTER_COUNTS,
     .csv_pos = 3, .csv_key = "rap"},
    {"rap_resolution", "--rap-resolution", MLT_OPTION_FLAG, FIELD(pss.rap_resolution), .methods = APPLIES_MCMC,
     .numbers = true, .help = "also scale image steps to a fixed size in pixels (thesis 4.1); implies --rap",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 4, .csv_key = "rap_resolution"},
    {"cdc", "--cdc", MLT_OPTION_FLAG, FIELD(pss.cdc), .methods = APPLIES_MCMC, .numbers = true,
     .help = "constrained discrete choices: small steps keep discrete numbers", .csv_group = MLT_CSV_AFTER_COUNTS,
     .csv_pos = 5, .csv_key = "cdc"},
    {"seed_paths", "--seed-paths", MLT_OPTION_INT, FIELD(seed_paths), .def = "100000", .lo = 1, .hi = 1L << 40,
     .arg = "N", .methods = APPLIES_CHAINS, .numbers = true, .help = "samples of the normalisation seed pass",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 6, .csv_key = "seed_paths"},
    {"seed_bdpt", "--seed-bdpt", MLT_OPTION_FLAG, FIELD(seed_bdpt), .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "mmlt, pitp: estimate b_k from BDPT samples, one per seed path and length (every technique; MMLT "
             "paper 4), instead of the seed pool's one-technique targets: the same b, a smaller normalisation "
             "error per seed path at 3-4x the seed pass's time",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 3, .csv_key = "seed_estimator", .csv_values = seed_estimators,
     .csv_effective = true},
    {"large_step", "--large-step", MLT_OPTION_CHOICE, FIELD(large_step), .choices = large_steps,
     .methods = APPLIES_MULTIPLEXED, .numbers = true, .help = "mmlt's large step (default mmlt; mctls: thesis 4.3)",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 1, .csv_key = "large_step"},
    {"hybrid_length", "--hybrid-length", MLT_OPTION_INT, FIELD(hybrid_length), .def = "6", .lo = 1,
     .hi = MAX_PATH_LENGTH, .arg = "K", .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "hybrid: MCTLS from path length K on, MMLT large steps below", .csv_group = MLT_CSV_BEFORE_COUNTS,
     .csv_pos = 2, .csv_key = "hybrid_length"},
    {"uniform_lengths", "--uniform-lengths", MLT_OPTION_FLAG, FIELD(uniform_lengths), .methods = APPLIES_MULTIPLEXED,
     .numbers = true, .help = "mmlt: equal mutations per path length instead of in proportion to b_k",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 4, .csv_key = "uniform_lengths"},
    {"progressive_norm", "--progressive-norm", MLT_OPTION_FLAG, FIELD(progressive_norm), .methods = APPLIES_MCMC,
     .numbers = true,
     .help = "b_k from the seed pass and every large step together (MMLT paper 4), the image rescaled to it per "
             "length (exact); costs one image per length and thread",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 9, .csv_key = "normalisation", .csv_values = normalisations,
     .conflict = progressive_conflict},
    {"one_chain", "--one-chain", MLT_OPTION_FLAG, FIELD(one_chain), .methods = APPLIES_MMLT, .numbers = true,
     .help = "mmlt: one chain per thread over all lengths, the length changed by large steps (MMLT paper 4's "
             "alternative), instead of one chain per length",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 10, .csv_key = "chains", .csv_values = chain_layouts,
     .csv_effective = true, .conflict = one_chain_conflict},
    {"max_heuristic", "--max-heuristic", MLT_OPTION_FLAG, FIELD(max_heuristic), .methods = APPLIES_PSSMLT,
     .numbers = true, .help = "pssmlt: Kelemen's maximum heuristic instead of the balance heuristic",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 5, .csv_key = "mis", .csv_values = mis_names},
    {"power_heuristic", "--power-heuristic", MLT_OPTION_FLAG, FIELD(power_heuristic), .methods = APPLIES_MMLT,
     .numbers = true,
     .help = "mmlt: the power heuristic (beta = 2) in the target instead of the balance heuristic (MMLT paper §6)",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 8, .csv_key = "power_heuristic", .conflict = power_conflict},
    {"small_step", "--small-step", MLT_OPTION_CHOICE, FIELD(small_step), .choices = small_steps,
     .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "mmlt/pitp small step (default pss; controlled: thesis 5.3 Alg. 4, root: Alg. 3, analysis only); the "
             "latter two use the Gaussian kernel",
     .csv_group = MLT_CSV_BEFORE_COUNTS, .csv_pos = 6, .csv_key = "small_step", .conflict = small_step_conflict},
    {"pitp_rate", "--pitp-rate", MLT_OPTION_DOUBLE, FIELD(pitp_rate), .def = "1", .lo = 0, .hi = 1, .arg = "P",
     .methods = APPLIES_PITP, .numbers = true,
     .help = "pitp: probability that a small step is preceded by the technique perturbation (1, the thesis's: "
             "every one; 0: MMLT's small steps). Tungsten's reversible jump (0.05) replaces a step instead: 5 % of "
             "its iterations are a technique move alone, 85 % small steps, so its 0.05 is P = 0.059 per small step "
             "here. Each kernel keeps the target, so any fixed P does"},
    {"mixing_image", "--mixing-image", MLT_OPTION_FLAG, FIELD(mixing_image), .methods = APPLIES_CHAINS,
     .help = "PREFIX.mixing.exr: per pixel, the chains' visits over their iterations there (low: chains sat; "
             "costs 1.4 % of a mutation)"},
    {"angle_stats", "--angle-stats", MLT_OPTION_FLAG, FIELD(angle_stats), .methods = APPLIES_MULTIPLEXED,
     .numbers = true, .help = "mmlt, pitp: angle change of every small step, PREFIX.angle.exr and .angle.csv",
     .conflict = angle_conflict},
    {"technique_k", "--technique-images", MLT_OPTION_INT, FIELD(technique_k), .lo = 1, .hi = MAX_PATH_LENGTH,
     .arg = "K", .methods = APPLIES_BDPT | APPLIES_PSSMLT | APPLIES_MMLT, .numbers = true,
     .help = "bdpt, pssmlt, mmlt (MMLT large steps): per-technique images of path length K (MMLT paper 5): "
             "PREFIX.tech-tT.exr/.png contribution of technique T; pssmlt/mmlt: PREFIX.count-tT.exr/.png chain "
             "samples in it, PREFIX.tech.csv shares; bdpt: PREFIX.tech.csv each technique's variance "
             "(the error it carries); pssmlt runs slower with it",
     .conflict = technique_conflict},
    /* the figure tools' and tests' own */
    {"mctls_tries", NULL, MLT_OPTION_INT, FIELD(mctls_tries), .lo = 0, .hi = MCTLS_MAX_TRIES,
     .methods = APPLIES_MULTIPLEXED, .numbers = true, .help = "MCTLS trials (mlt.h)", .conflict = mctls_conflict},
    {"mctls_count_t0", NULL, MLT_OPTION_FLAG, FIELD(mctls_count_t0), .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "MCTLS trials among k + 2 techniques (mlt.h)", .conflict = mctls_conflict},
    {"mctls_recompute", NULL, MLT_OPTION_FLAG, FIELD(mctls_recompute), .methods = APPLIES_MULTIPLEXED,
     .help = "MCTLS re-evaluates the current state's trials every step (mlt.h)"},
    {"ctrl_unit_ratio", NULL, MLT_OPTION_FLAG, FIELD(ctrl_unit_ratio), .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "tests only: a broken controlled step"},
    {"veach_lens", "--mlt-lens", MLT_OPTION_DOUBLE, FIELD(veach_lens), .def = "0.3", .lo = 0, .hi = 1, .arg = "P",
     .methods = APPLIES_VEACH, .numbers = true,
     .help = "mlt: probability that an iteration is Veach's lens perturbation (else the bidirectional mutation; the "
             "harness's default)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 7, .csv_key = "mlt_lens", .csv_own = true,
     .conflict = veach_mix_conflict},
    {"veach_caustic", "--mlt-caustic", MLT_OPTION_DOUBLE, FIELD(veach_caustic), .def = "0.2", .lo = 0, .hi = 1,
     .arg = "P", .methods = APPLIES_VEACH, .numbers = true,
     .help = "mlt: probability that an iteration is Veach's caustic perturbation (the harness's default; with "
             "--mlt-lens, --mlt-lens-subpath and --mlt-multichain at most 1, the rest bidirectional mutations)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 8, .csv_key = "mlt_caustic", .csv_own = true,
     .conflict = veach_mix_conflict},
    {"veach_lens_subpath", "--mlt-lens-subpath", MLT_OPTION_DOUBLE, FIELD(veach_lens_subpath), .def = "0.1", .lo = 0,
     .hi = 1, .arg = "P", .methods = APPLIES_VEACH, .numbers = true,
     .help = "mlt: probability that an iteration is Veach's lens subpath mutation (a new camera subpath through a "
             "uniform raster position; the harness's default)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 11, .csv_key = "mlt_lens_subpath", .csv_own = true,
     .conflict = veach_mix_conflict},
    {"veach_multichain", "--mlt-multichain", MLT_OPTION_DOUBLE, FIELD(veach_multichain), .def = "0.1", .lo = 0, .hi = 1,
     .arg = "P", .methods = APPLIES_VEACH, .numbers = true,
     .help = "mlt: probability that an iteration is Veach's multi-chain perturbation (the lens perturbation through "
             "specular chains between non-delta vertices, each turned as the caustic one; the harness's default)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 12, .csv_key = "mlt_multichain", .csv_own = true,
     .conflict = veach_mix_conflict},
    {"fused", "--fused", MLT_OPTION_CHOICE, FIELD(fused), .choices = fused_moves, .arg = "LIST",
     .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help =
         "mmlt, pitp: fused perturbations (Otsu et al. 2017): none, or a +-joined set of lens, caustic and "
         "multichain in that order (e.g. lens+caustic+multichain; equal shares): Veach's perturbation of the chain's "
         "path, mapped back to primary sample space by the inverse of its technique; PREFIX.csv rows fused-lens, "
         "fused-caustic, fused-multichain",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 9, .csv_key = "fused", .csv_own = true, .csv_if = fused_on},
    {"fused_rate", "--fused-rate", MLT_OPTION_DOUBLE, FIELD(fused_rate), .def = "0.5", .lo = 0, .hi = 1, .arg = "P",
     .methods = APPLIES_MULTIPLEXED, .numbers = true,
     .help = "mmlt, pitp with --fused: the share of small steps that are a fused perturbation (the harness's "
             "default, half: Otsu et al. state no value)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 10, .csv_key = "fused_rate", .csv_own = true, .csv_if = fused_on},
    {"large_step_mis", "--large-step-mis", MLT_OPTION_FLAG, FIELD(large_step_mis), .methods = APPLIES_PSSMLT,
     .numbers = true,
     .help = "pssmlt: Kelemen et al.'s weights, the large steps also counted as independent samples: a state's "
             "splat weighs (a + [large]) / (f / b + p_large) instead of a / (f / b) (Tungsten's kelemen_mlt)",
     .csv_group = MLT_CSV_AFTER_COUNTS, .csv_pos = 13, .csv_key = "large_step_mis", .csv_own = true,
     .csv_if = large_step_mis_on},
    {"lens_broken_t", NULL, MLT_OPTION_FLAG, FIELD(lens_broken_t), .methods = APPLIES_MULTIPLEXED | APPLIES_VEACH,
     .numbers = true, .help = "tests only: a broken lens perturbation"},
    {"veach_broken_t", NULL, MLT_OPTION_FLAG, FIELD(veach_broken_t), .methods = APPLIES_VEACH, .numbers = true,
     .help = "tests only: a broken bidirectional mutation"},
    {"time_proposals", NULL, MLT_OPTION_FLAG, FIELD(time_proposals), .methods = APPLIES_CHAINS,
     .help = "each proposal's time in the statistics"},
    /* what bin/render's shared options (pt and bdpt read them too) set */
    {"seed", NULL, MLT_OPTION_INT, FIELD(seed), .lo = 0, .hi = 1e18, .methods = APPLIES_CHAINS, .numbers = true,
     .help = "random seed"},
    {"threads", NULL, MLT_OPTION_INT, FIELD(threads), .lo = 1, .hi = 1024, .methods = APPLIES_CHAINS, .numbers = true,
     .help = "worker threads"},
    {"max_length", NULL, MLT_OPTION_INT, FIELD(max_length), .lo = 1, .hi = MAX_PATH_LENGTH, .methods = APPLIES_CHAINS,
     .numbers = true, .help = "maximum path length"},
    {"min_length", NULL, MLT_OPTION_INT, FIELD(min_length), .lo = 0, .hi = MAX_PATH_LENGTH, .methods = APPLIES_CHAINS,
     .numbers = true, .help = "minimum path length"},
    {"mutations", NULL, MLT_OPTION_INT, FIELD(mutations), .lo = 0, .hi = 1e18, .methods = APPLIES_CHAINS,
     .numbers = true, .help = "mutation budget over all threads"},
    {"seconds", NULL, MLT_OPTION_DOUBLE, FIELD(seconds), .lo = 0, .hi = 1e9, .methods = APPLIES_CHAINS, .numbers = true,
     .help = "time budget"},
    {"cpu_time", NULL, MLT_OPTION_FLAG, FIELD(cpu_time), .methods = APPLIES_CHAINS, .numbers = true,
     .help = "the time budget in CPU seconds per thread"},
};
const size_t mlt_options_count = sizeof mlt_options / sizeof mlt_options[0];

/* ---- what is derived from it ---- */

const struct mlt_option *mlt_option_find(const char *key)
{
    for (size_t i = 0; i < mlt_options_count; i++)
        if (!strcmp(mlt_options[i].key, key)) return &mlt_options[i];
    return NULL;
}

double mlt_option_get(const struct mlt_option *d, const struct mlt_opts *o)
{
    const char *p = (const char *)o + d->offset;
    if (d->type == MLT_OPTION_DOUBLE) return *(const double *)p;
    if (d->size == 1) return *(const bool *)p;
    if (d->size == sizeof(int)) return *(const int *)p;
    int64_t v;
    memcpy(&v, p, sizeof v);
    return (double)v;
}

void mlt_option_set(const struct mlt_option *d, struct mlt_opts *o, double v)
{
    char *p = (char *)o + d->offset;
    if (d->type == MLT_OPTION_DOUBLE)
        *(double *)p = v;
    else if (d->size == 1)
        *(bool *)p = v != 0;
    else if (d->size == sizeof(int))
        *(int *)p = (int)v;
    else {
        int64_t i = (int64_t)v;
        memcpy(p, &i, sizeof i);
    }
}

static double default_value(const struct mlt_option *d)
{
    struct mlt_opts o;
    mlt_opts_defaults(&o);
    return mlt_option_get(d, &o);
}

void mlt_opts_defaults(struct mlt_opts *o)
{
    *o = (struct mlt_opts){0};
    pss_opts_default(&o->pss, 1, 1);
    for (size_t i = 0; i < mlt_options_count; i++) {
        const struct mlt_option *d = &mlt_options[i];
        if (d->def) mlt_option_set(d, o, strtod(d->def, NULL)); /* no choice has a def */
    }
}

bool mlt_option_at_default(const struct mlt_option *d, const struct mlt_opts *o)
{
    return mlt_option_get(d, o) == default_value(d);
}

void mlt_option_format(const struct mlt_option *d, const struct mlt_opts *o, bool csv, char *buf, size_t n)
{
    double v = mlt_option_get(d, o);
    if (csv && d->csv_effective && !(d->methods & mlt_method_mask(o->method))) v = default_value(d);
    if (d->type == MLT_OPTION_CHOICE)
        snprintf(buf, n, "%s", d->choices[(int)v]);
    else if (csv && d->csv_values)
        snprintf(buf, n, "%s", d->csv_values[v != 0]);
    else if (d->type == MLT_OPTION_DOUBLE)
        snprintf(buf, n, csv ? "%g" : "%.17g", v);
    else if (d->size == sizeof(uint64_t)) { /* exact, above 2^53 too (seeds) */
        uint64_t u;
        memcpy(&u, (const char *)o + d->offset, sizeof u);
        snprintf(buf, n, "%llu", (unsigned long long)u);
    } else
        snprintf(buf, n, "%lld", (long long)v);
}

int mlt_options_identity(const struct mlt_opts *o, char *buf, size_t n)
{
    int len = 0;
    char v[64];
    for (size_t i = 0; i < mlt_options_count && len >= 0 && (size_t)len < n; i++) {
        const struct mlt_option *d = &mlt_options[i];
        if (!d->numbers) continue;
        mlt_option_format(d, o, false, v, sizeof v);
        len += snprintf(buf + len, n - (size_t)len, " %s=%s", d->key, v);
    }
    return len;
}

size_t mlt_options_csv(enum mlt_csv_group g, const struct mlt_option **out, size_t max)
{
    size_t m = 0;
    for (int pos = 1; m < max; pos++) {
        size_t before = m;
        for (size_t i = 0; i < mlt_options_count; i++)
            if (mlt_options[i].csv_group == g && g != MLT_CSV_NONE && mlt_options[i].csv_pos == pos && m < max)
                out[m++] = &mlt_options[i];
        if (m == before) break; /* positions run 1, 2, ... without a gap */
    }
    return m;
}

bool mlt_options_check(const struct mlt_opts *o, char *err, size_t errlen)
{
    for (size_t i = 0; i < mlt_options_count; i++) {
        const struct mlt_option *d = &mlt_options[i];
        if (d->conflict && !mlt_option_at_default(d, o) && d->conflict(o, err, errlen)) return false;
    }
    return true;
}
