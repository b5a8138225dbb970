/* Mixing diagnostics per path length and over all (see mixing.h). */
#include "stats/mixing.h"
#include "base/util.h"
#include "stats/chain_ess.h"
#include "stats/chain_rhat.h"
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* What the all row gathers over the groups. */
struct mixing_acc {
    double z_sum;
    int z_count, stuck, chains;
};

/* The chain's values at multiples of stride S (a multiple of its own), the first n of them. */
static void aligned(const struct chain_trace *t, const float *v, long S, size_t n, double *out)
{
    size_t f = (size_t)(S / t->stride);
    for (size_t i = 0; i < n; i++)
        out[i] = v[i * f];
}

/* Stan's bulk ESS: rank-normalised split chains. */
static double bulk_ess(const double *x, int m, size_t n)
{
    double *s = xmalloc((size_t)m * n * sizeof *s);
    size_t h = split_chains(x, m, n, s);
    rank_normalise(s, (size_t)(2 * m) * h, s);
    double e = ess_of(s, 2 * m, h);
    free(s);
    return e;
}

/* One chain's tau in draws, on its normal scores. */
static double chain_tau(const double *x, size_t n)
{
    double *z = xmalloc(n * sizeof *z);
    rank_normalise(x, n, z);
    double tau = ess_tau(z, 1, n);
    free(z);
    return tau;
}

/* The run above which a chain of n iterations at its length's mean acceptance a is stuck (mixing.h). */
static double stuck_threshold(long n, double a)
{
    double l = 0;
    if (a > 0 && a < 1 && (double)n * a > 1e-3) l = log(1e-3 / ((double)n * a)) / log1p(-a);
    return fmax(fmax(l, 0.01 * (double)n), MIXING_STUCK_MIN);
}

/* The start-up z of one chain's n contributions, tau in draws; false when it has no spread. */
static bool startup_z(const double *x, size_t n, double tau, double *z)
{
    size_t h = n / 100 > 0 ? n / 100 : 1;
    double var = gsl_stats_variance(x, 1, n);
    if (!(var > 0) || !(tau > 0) || h >= n) return false;
    double d = gsl_stats_mean(x, 1, h) - gsl_stats_mean(x + h, 1, n - h);
    *z = d / sqrt(var * tau * (1.0 / (double)h + 1.0 / (double)(n - h)));
    return true;
}

/* The estimates from the aligned traces X (contributions) and Y (targets) of m chains of n draws. */
static void estimates(const double *X, const double *Y, int m, size_t n, long S, struct mixing_row *r,
                      struct mixing_acc *acc)
{
    r->rhat_contrib = rhat_rank(X, m, n);
    r->rhat_target = rhat_rank(Y, m, n);
    double ex = bulk_ess(X, m, n), ey = bulk_ess(Y, m, n);
    r->ess_total = isnan(ex) ? ey : isnan(ey) ? ex : fmin(ex, ey);
    r->tau = (double)m * (double)n * (double)S / r->ess_total;
    r->ess_chain_min = INFINITY;
    double zs = 0;
    int zc = 0;
    for (int c = 0; c < m; c++) {
        double tx = chain_tau(X + (size_t)c * n, n), ty = chain_tau(Y + (size_t)c * n, n);
        double tmax = isnan(tx) ? ty : isnan(ty) ? tx : fmax(tx, ty);
        if (!isnan(tmax)) r->ess_chain_min = fmin(r->ess_chain_min, (double)n / tmax);
        double z;
        if (startup_z(X + (size_t)c * n, n, tx, &z)) zs += z, zc++;
    }
    if (isinf(r->ess_chain_min)) r->ess_chain_min = NAN;
    r->startup_z = zc ? zs / sqrt(zc) : NAN;
    acc->z_sum += zs;
    acc->z_count += zc;
}

/* The row of the m chains tc (one length), which ran at least one iteration each. */
static void group_row(const struct chain_trace *const *tc, int m, struct mixing_row *r, struct mixing_acc *acc)
{
    *r = (struct mixing_row){.k = tc[0]->k,
                             .chains = m,
                             .rhat_contrib = NAN,
                             .rhat_target = NAN,
                             .ess_total = NAN,
                             .ess_chain_min = NAN,
                             .tau = NAN,
                             .startup_z = NAN};
    long moved = 0, S = 1;
    size_t n = TRACE_CAP;
    for (int c = 0; c < m; c++) {
        r->draws += tc[c]->n;
        moved += tc[c]->moved;
        if (tc[c]->longest > r->longest_max) r->longest_max = tc[c]->longest;
        if (tc[c]->stride > S) S = tc[c]->stride;
    }
    int stuck = 0;
    for (int c = 0; c < m; c++) {
        stuck += (double)tc[c]->longest > stuck_threshold(tc[c]->n, (double)moved / (double)r->draws);
        size_t f = (size_t)(S / tc[c]->stride), held = ((size_t)tc[c]->len + f - 1) / f;
        if (held < n) n = held;
    }
    r->thin = S;
    r->stuck_share = (double)stuck / m;
    acc->stuck += stuck;
    acc->chains += m;
    if (n >= 4) {
        double *X = xmalloc((size_t)m * n * sizeof *X), *Y = xmalloc((size_t)m * n * sizeof *Y);
        for (int c = 0; c < m; c++) {
            aligned(tc[c], tc[c]->contrib, S, n, X + (size_t)c * n);
            aligned(tc[c], tc[c]->target, S, n, Y + (size_t)c * n);
        }
        estimates(X, Y, m, n, S, r, acc);
        free(X);
        free(Y);
    }
    bool rhat_bad = r->rhat_contrib > MIXING_RHAT_MAX || r->rhat_target > MIXING_RHAT_MAX;
    r->warn = (rhat_bad ? MIXING_RHAT : 0) | (!(r->ess_total >= MIXING_ESS_MIN) ? MIXING_ESS : 0) |
              (stuck ? MIXING_STUCK : 0);
}

/* NaN-ignoring max and min. */
static double nmax(double a, double b) { return isnan(a) ? b : isnan(b) ? a : fmax(a, b); }
static double nmin(double a, double b) { return isnan(a) ? b : isnan(b) ? a : fmin(a, b); }

/* The all row from the length rows r[0..n). */
static void all_row(const struct mixing_row *r, int n, const struct mixing_acc *acc, struct mixing_row *all)
{
    *all = (struct mixing_row){.k = -1, .rhat_contrib = NAN, .rhat_target = NAN, .ess_chain_min = NAN, .tau = NAN};
    for (int i = 0; i < n; i++) {
        all->chains += r[i].chains;
        all->draws += r[i].draws;
        if (r[i].thin > all->thin) all->thin = r[i].thin;
        all->rhat_contrib = nmax(all->rhat_contrib, r[i].rhat_contrib);
        all->rhat_target = nmax(all->rhat_target, r[i].rhat_target);
        if (!isnan(r[i].ess_total)) all->ess_total += r[i].ess_total;
        all->ess_chain_min = nmin(all->ess_chain_min, r[i].ess_chain_min);
        all->tau = nmax(all->tau, r[i].tau);
        if (r[i].longest_max > all->longest_max) all->longest_max = r[i].longest_max;
        all->warn |= r[i].warn;
    }
    all->stuck_share = acc->chains ? (double)acc->stuck / acc->chains : 0;
    all->startup_z = acc->z_count ? acc->z_sum / sqrt(acc->z_count) : NAN;
}

int mixing_rows(const struct chain_trace *t, int n, struct mixing_row *rows, int max)
{
    const struct chain_trace **tc = xmalloc((size_t)(n > 0 ? n : 1) * sizeof *tc);
    struct mixing_acc acc = {0};
    int nr = 0, kmax = 0;
    for (int i = 0; i < n; i++)
        if (t[i].k > kmax) kmax = t[i].k;
    for (int k = 0; k <= kmax; k++) {
        int m = 0;
        for (int i = 0; i < n; i++)
            if (t[i].k == k && t[i].n > 0) tc[m++] = &t[i];
        if (!m) continue;
        ASSERT(nr < max);
        group_row(tc, m, &rows[nr++], &acc);
    }
    free(tc);
    if (nr == 1 && rows[0].k == 0) { /* PSSMLT: its one group is the run */
        rows[0].k = -1;
        return 1;
    }
    ASSERT(nr < max);
    all_row(rows, nr, &acc, &rows[nr]);
    return nr + 1;
}

static void row_label(const struct mixing_row *r, char *buf, size_t len)
{
    if (r->k < 0)
        snprintf(buf, len, "all");
    else
        snprintf(buf, len, "%d", r->k);
}

/* The rows, each opened by "RUN," when run is given and closed by ",ESS_PER_S" when seconds > 0. */
static void write_rows(FILE *f, const char *run, const struct mixing_row *rows, int n, double seconds)
{
    for (int i = 0; i < n; i++) {
        const struct mixing_row *r = &rows[i];
        char k[16], w[32] = "";
        row_label(r, k, sizeof k);
        static const char *const words[] = {"rhat", "ess", "stuck"};
        for (int b = 0; b < 3; b++)
            if (r->warn & (1u << b)) snprintf(w + strlen(w), sizeof w - strlen(w), "%s%s", *w ? "+" : "", words[b]);
        if (run) fprintf(f, "%s,", run);
        fprintf(f, "%s,%d,%ld,%ld,%.4f,%.4f,%.1f,%.1f,%.4g,%ld,%.4f,%.3f,%s", k, r->chains, r->draws, r->thin,
                r->rhat_contrib, r->rhat_target, r->ess_total, r->ess_chain_min, r->tau, r->longest_max, r->stuck_share,
                r->startup_z, *w ? w : "ok");
        if (run) fprintf(f, ",%.3f,%.4g", seconds, seconds > 0 ? r->ess_total / seconds : NAN);
        fputc('\n', f);
    }
}

static const char mixing_cols[] = "length,chains,draws,thin,rhat_contrib,rhat_target,ess_total,ess_per_chain_min,tau,"
                                  "longest_reject_run_max,stuck_share,startup_z,warning";

void mixing_write_csv(FILE *f, const struct mixing_row *rows, int n)
{
    fprintf(f, "%s\n", mixing_cols);
    write_rows(f, NULL, rows, n, 0);
}

void mixing_runs_header(FILE *f) { fprintf(f, "run,%s,seconds,ess_per_s\n", mixing_cols); }

void mixing_write_run(FILE *f, const char *run, const struct mixing_row *rows, int n, double seconds)
{
    write_rows(f, run, rows, n, seconds);
}

/* "; WHAT at lengths 3, 4" for the length rows (all but the last, unless it is the only row)
 * carrying bit; nothing when none does. */
static void append_rows(char *buf, size_t len, const struct mixing_row *rows, int n, unsigned bit, const char *what)
{
    int nlen = n > 1 ? n - 1 : n, hits = 0;
    for (int i = 0; i < nlen; i++) {
        if (!(rows[i].warn & bit)) continue;
        size_t u = strlen(buf);
        char k[16];
        row_label(&rows[i], k, sizeof k);
        if (!hits++)
            snprintf(buf + u, len - u, "%s%s at %s%s", *buf ? "; " : "", what, rows[i].k < 0 ? "" : "lengths ", k);
        else
            snprintf(buf + u, len - u, ", %s", k);
    }
}

bool mixing_warning_line(const struct mixing_row *rows, int n, char *buf, size_t len)
{
    buf[0] = 0;
    if (n < 1 || !rows[n - 1].warn) return false;
    char what[64];
    snprintf(what, sizeof what, "R-hat above %.2f", MIXING_RHAT_MAX);
    append_rows(buf, len, rows, n, MIXING_RHAT, what);
    snprintf(what, sizeof what, "ESS under %.0f", MIXING_ESS_MIN);
    append_rows(buf, len, rows, n, MIXING_ESS, what);
    append_rows(buf, len, rows, n, MIXING_STUCK, "stuck chains");
    const struct mixing_row *all = &rows[n - 1];
    size_t u = strlen(buf);
    snprintf(buf + u, len - u, " (largest R-hat %.3f, %.0f %% of %d chains stuck)",
             nmax(all->rhat_contrib, all->rhat_target), 100 * all->stuck_share, all->chains);
    return true;
}
