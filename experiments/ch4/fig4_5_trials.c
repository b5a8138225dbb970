/* Fig. 4.5's curves from independent trials (see fig4_5_trials.h). */
#include "ch4/fig4_5_trials.h"
#include "base/parallel.h"
#include "base/util.h"
#include "mc/integrator.h"
#include "mcmc/mctls.h"
#include "stats/indep_accept.h"
#include <math.h>
#include <stdlib.h>

const char *const trial_stat_names[TS_COUNT] = {"accept_mmlt",   "accept_mctls",      "accept_ratio",
                                                "light_ratio",   "given_light_ratio", "techniques_with_light",
                                                "techniques_cv", "accept_mctls_mean", "given_light_ratio_mean"};

#define GROUPS 16

/* One thread's pairs with light: MMLT's draws (a technique's target, > 0) and their pairs. */
struct draw_list {
    long n, cap;
    double *w;
    long *cluster;
};

struct trials_job {
    const struct scene *sc;
    int k, K, threads;
    long pairs;
    uint64_t seed;
    double *sum; /* per pair: the sum of its k + 1 targets */
    int *n;      /* per pair: its techniques with a target */
    struct draw_list *lists;
    struct progress prog;
};

static void list_push(struct draw_list *l, double w, long cluster)
{
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 4096;
        l->w = xrealloc(l->w, (size_t)l->cap * sizeof *l->w);
        l->cluster = xrealloc(l->cluster, (size_t)l->cap * sizeof *l->cluster);
    }
    l->w[l->n] = w;
    l->cluster[l->n++] = cluster;
}

static void trials_worker(int tid, void *p)
{
    struct trials_job *j = p;
    struct path_ctx pc = {.sc = j->sc, .max_length = j->K};
    struct scratch *w = xcalloc(1, sizeof *w);
    double pi[MAX_PATH_LENGTH + 2];
    struct splat_list *sp = xmalloc((MAX_PATH_LENGTH + 2) * sizeof *sp);
    struct sampler_independent s;
    long done = 0;
    for (long i = tid; i < j->pairs; i += j->threads) {
        /* a stream per (length, pair): the lengths' pairs are independent of each other too */
        sampler_independent_init(&s, j->seed, ((uint64_t)j->k << 40) | (uint64_t)i);
        j->sum[i] = mctls_trials(&pc, &s.base, w, j->k, pi, sp);
        j->n[i] = 0;
        for (int t = 1; t <= j->k + 1; t++)
            if (pi[t] > 0) {
                j->n[i]++;
                list_push(&j->lists[tid], pi[t], i);
            }
        if (++done % 4096 == 0) progress_add(&j->prog, 4096);
    }
    free(sp);
    free(w);
}

/* A draw list of one weight per pair (zero weights left out). */
static struct weighted_draws per_pair(const double *v, long pairs)
{
    struct weighted_draws d = {.w = xmalloc((size_t)pairs * sizeof(double)),
                               .cluster = xmalloc((size_t)pairs * sizeof(long)),
                               .clusters = pairs,
                               .per_cluster = 1,
                               .groups = GROUPS};
    for (long i = 0; i < pairs; i++)
        if (v[i] > 0) d.w[d.n] = v[i], d.cluster[d.n++] = i;
    return d;
}

static void set(struct trials_table *t, enum trial_stat s, int k, const double *theta)
{
    t->value[s][k] = theta[0];
    t->se[s][k] = jack_se(theta, GROUPS);
}

/* The statistics of length k from its pairs (replicate by replicate, so that the derived ones get
 * jackknife errors too). */
static void summarise(struct trials_job *j, struct trials_table *t)
{
    int k = j->k;
    long P = j->pairs;
    double *v = xmalloc((size_t)P * sizeof *v), *mean = xmalloc((size_t)P * sizeof *mean);
    double light[GROUPS + 1], nn[GROUPS + 1], n2[GROUPS + 1], a_mmlt[GROUPS + 1], a_mctls[GROUPS + 1],
        a_mean[GROUPS + 1], r[TS_COUNT][GROUPS + 1];
    for (long i = 0; i < P; i++)
        v[i] = j->n[i] > 0;
    jack_mean(v, P, GROUPS, light);
    for (long i = 0; i < P; i++)
        v[i] = j->n[i];
    jack_mean(v, P, GROUPS, nn);
    for (long i = 0; i < P; i++)
        v[i] = (double)j->n[i] * j->n[i];
    jack_mean(v, P, GROUPS, n2);
    /* MMLT's draws: every technique of every pair, k + 1 per pair (threads' lists in order) */
    struct weighted_draws d = {.clusters = P, .per_cluster = k + 1, .groups = GROUPS};
    for (int th = 0; th < j->threads; th++)
        d.n += j->lists[th].n;
    d.w = xmalloc((size_t)(d.n ? d.n : 1) * sizeof *d.w);
    d.cluster = xmalloc((size_t)(d.n ? d.n : 1) * sizeof *d.cluster);
    for (long th = 0, at = 0; th < j->threads; th++)
        for (long e = 0; e < j->lists[th].n; e++, at++)
            d.w[at] = j->lists[th].w[e], d.cluster[at] = j->lists[th].cluster[e];
    indep_accept(&d, a_mmlt);
    free(d.w);
    free(d.cluster);
    d = per_pair(j->sum, P);
    indep_accept(&d, a_mctls);
    free(d.w);
    free(d.cluster);
    for (long i = 0; i < P; i++)
        mean[i] = j->n[i] > 0 ? j->sum[i] / j->n[i] : 0;
    d = per_pair(mean, P);
    indep_accept(&d, a_mean);
    free(d.w);
    free(d.cluster);
    for (int g = 0; g <= GROUPS; g++) {
        double lr = (k + 1) * light[g] / nn[g], tech = nn[g] / light[g];
        r[TS_ACCEPT_MMLT][g] = a_mmlt[g];
        r[TS_ACCEPT_MCTLS][g] = a_mctls[g];
        r[TS_ACCEPT_RATIO][g] = a_mctls[g] / a_mmlt[g];
        r[TS_LIGHT_RATIO][g] = lr;
        r[TS_GIVEN_LIGHT_RATIO][g] = a_mctls[g] / a_mmlt[g] / lr;
        r[TS_TECHNIQUES][g] = tech;
        r[TS_TECHNIQUES_CV][g] = sqrt(fmax(0, n2[g] / light[g] - tech * tech)) / tech;
        r[TS_ACCEPT_MCTLS_MEAN][g] = a_mean[g];
        r[TS_GIVEN_LIGHT_RATIO_MEAN][g] = a_mean[g] / a_mmlt[g] / lr;
    }
    for (int s = 0; s < TS_COUNT; s++)
        set(t, s, k, r[s]);
    free(v);
    free(mean);
}

bool fig45_trials(const struct scene *sc, int K, long pairs, uint64_t seed, int threads, bool progress,
                  struct trials_table *t)
{
    if (K < 2 || K > MAX_PATH_LENGTH || pairs < 2 * GROUPS) return false;
    t->K = K;
    struct trials_job j = {.sc = sc, .K = K, .threads = threads, .pairs = pairs, .seed = seed};
    j.sum = xmalloc((size_t)pairs * sizeof *j.sum);
    j.n = xmalloc((size_t)pairs * sizeof *j.n);
    j.lists = xcalloc((size_t)threads, sizeof *j.lists);
    progress_init(&j.prog, "fig4.5 trials", pairs * (K - 1), progress);
    for (j.k = 2; j.k <= K; j.k++) {
        for (int th = 0; th < threads; th++)
            j.lists[th].n = 0;
        parallel_run(threads, trials_worker, &j);
        summarise(&j, t);
    }
    progress_finish(&j.prog);
    for (int th = 0; th < threads; th++) {
        free(j.lists[th].w);
        free(j.lists[th].cluster);
    }
    free(j.lists);
    free(j.sum);
    free(j.n);
    return true;
}

const struct column fig45_trials_cols[] = {COL_INT(struct trial_row, "length", "%d", length),
                                           COL_STRING(struct trial_row, "statistic", statistic),
                                           COL_DOUBLE(struct trial_row, "value", "%.6g", value),
                                           COL_DOUBLE(struct trial_row, "se", "%.3g", se),
                                           {0}};

void fig45_trials_rows(struct table *tab, const struct trials_table *t)
{
    for (int k = 2; k <= t->K; k++)
        for (int s = 0; s < TS_COUNT; s++)
            table_row(tab, &(struct trial_row){k, trial_stat_names[s], t->value[s][k], t->se[s][k]});
}
