/* Generic statistical regression check: compares per-row means with standard errors in a current
 * CSV against a committed baseline CSV. Rows are matched by key columns; for each row
 *   z = (mean - mean_b) / sqrt(se^2 + se_b^2),
 * two-sided p-value from the normal distribution, or, when a count column is given (number of
 * independent runs behind each mean), from Student's t with Welch-Satterthwaite degrees of freedom.
 * A row differs significantly when p < alpha_1 = 1 - (1 - alpha)^(1/m) (Sidak over the m compared
 * rows). A baseline row missing from the current file is a failure. Prints a per-row verdict table
 * (Markdown). Exit status: 0 no significant difference, 1 some difference or missing row, 2 bad input.
 * CSV: tools/stats_csv.h. */
#include "base/util.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/text_out.h"
#include "tools/stats_csv.h"
#include <errno.h>
#include <float.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const prog = "check_stats";

static struct stats_table load(const char *file, const struct stats_cols *cols)
{
    FILE *f = fopen(file, "r");
    if (!f) opts_fail(prog, "%s: %s", file, strerror(errno));
    struct stats_table t;
    char err[512];
    bool ok = stats_csv_read(f, file, cols, &t, err, sizeof err);
    fclose(f);
    if (!ok) opts_fail(prog, "%s", err);
    return t;
}

struct files {
    const char *name[2];
    int n;
};

static void file_arg(const char *prog_, const char *arg, void *ctx)
{
    struct files *f = ctx;
    if (f->n == 2) opts_fail(prog_, "unexpected argument '%s': expected BASELINE.csv CURRENT.csv (see --help)", arg);
    f->name[f->n++] = arg;
}

struct args {
    const char *keyarg, *mean, *se, *count, *out;
    double alpha;
    struct files fl;
};

static void parse(int argc, char **argv, struct args *a)
{
    const struct opt opts[] = {
        {"--key", OPT_STRING, OPT_DST(a->keyarg), .arg = "COLS",
         .help = "comma-separated key columns matching rows (default: first column)"},
        {"--mean", OPT_STRING, OPT_DST(a->mean), .arg = "COL", .help = "column with the mean", .def = "mean"},
        {"--se", OPT_STRING, OPT_DST(a->se), .arg = "COL", .help = "column with its standard error", .def = "se"},
        {"--count", OPT_STRING, OPT_DST(a->count), .arg = "COL",
         .help =
             "column with the number of runs behind the mean: p-values from Student's t with Welch-Satterthwaite df "
             "instead of the normal distribution"},
        {"--alpha", OPT_DOUBLE, OPT_DST(a->alpha), .arg = "A", .lo = DBL_TRUE_MIN, .hi = 1 - 0x1p-53,
         .expect = "a number in (0, 1)", .help = "family-wise significance level, Sidak-corrected over rows",
         .def = "0.01"},
        {"--out", OPT_STRING, OPT_DST(a->out), .arg = "FILE",
         .help = "also write the verdict table (Markdown) to FILE"},
        {0}};
    opts_parse(
        &(struct opts_spec){.prog = prog,
                            .usage = "usage: check_stats [options] BASELINE.csv CURRENT.csv\n",
                            .about = "Compares per-row means (with standard errors) of CURRENT against BASELINE.\n",
                            .tail = "exit status: 0 consistent, 1 significant difference or missing row, 2 bad input\n",
                            .opts = opts,
                            .positional = file_arg,
                            .ctx = &a->fl},
        argc, argv);
    if (a->fl.n != 2) opts_fail(prog, "expected BASELINE.csv CURRENT.csv (see --help)");
}

/* The key columns into cols (names stored in keys): --key's list, or the baseline's first column. */
static void key_columns(const struct args *a, struct stats_cols *cols, char keys[STATS_MAXKEY][STATS_NAME])
{
    const char *p = a->keyarg;
    if (!p) {
        FILE *f = fopen(a->fl.name[0], "r");
        if (!f) opts_fail(prog, "%s: %s", a->fl.name[0], strerror(errno));
        char err[512];
        bool ok = stats_csv_first_column(f, a->fl.name[0], keys[0], err, sizeof err);
        fclose(f);
        if (!ok) opts_fail(prog, "%s", err);
        cols->key[cols->nkeys++] = keys[0];
        return;
    }
    while (*p) {
        size_t l = strcspn(p, ",");
        if (l == 0 || l >= STATS_NAME || cols->nkeys == STATS_MAXKEY)
            opts_fail(prog, "--key: bad column list '%s'", a->keyarg);
        memcpy(keys[cols->nkeys], p, l);
        keys[cols->nkeys][l] = 0;
        cols->key[cols->nkeys] = keys[cols->nkeys];
        cols->nkeys++;
        p += l;
        if (*p) p++;
    }
}

/* The two-sided p-value of the current row's difference from the baseline's, its z in *z: normal,
 * or (welch) Student's t with Welch-Satterthwaite degrees of freedom. */
static double p_value(const struct stats_row *rb, const struct stats_row *rc, bool welch, double *z)
{
    double s = sqrt(rb->se * rb->se + rc->se * rc->se), d = rc->mean - rb->mean;
    *z = s > 0 ? d / s : (d == 0 ? 0 : copysign(INFINITY, d));
    if (!isfinite(*z)) return 0;
    if (!welch) return 2 * gsl_cdf_ugaussian_Q(fabs(*z));
    double vb = rb->se * rb->se, vc = rc->se * rc->se;
    double den = vb * vb / (rb->count - 1) + vc * vc / (rc->count - 1);
    double df = den > 0 ? (vb + vc) * (vb + vc) / den : 1e9;
    return 2 * gsl_cdf_tdist_Q(fabs(*z), df);
}

/* The verdict rows into f, one per baseline row; returns the failures (missing rows included). */
static int compare(FILE *f, const struct stats_table *b, const struct stats_table *c, bool welch, double a1)
{
    int fails = 0;
    for (int i = 0; i < b->n; i++) {
        const struct stats_row *rb = &b->rows[i], *rc = NULL;
        for (int j = 0; j < c->n; j++)
            if (!strcmp(c->rows[j].key, rb->key)) rc = &c->rows[j];
        if (!rc) {
            fprintf(f, "| %s | %.4g ± %.2g | missing | | | FAIL |\n", rb->key, rb->mean, rb->se);
            fails++;
            continue;
        }
        double z, p = p_value(rb, rc, welch, &z);
        int fail = p < a1;
        fails += fail;
        fprintf(f, "| %s | %.4g ± %.2g | %.4g ± %.2g | %+.2f | %.2g | %s |\n", rb->key, rb->mean, rb->se, rc->mean,
                rc->se, z, p, fail ? "FAIL" : "ok");
    }
    return fails;
}

int main(int argc, char **argv)
{
    struct args a = {0};
    parse(argc, argv, &a);
    char keys[STATS_MAXKEY][STATS_NAME];
    struct stats_cols cols = {.mean = a.mean, .se = a.se, .count = a.count};
    key_columns(&a, &cols, keys);
    const char *base = a.fl.name[0], *cur = a.fl.name[1];
    struct stats_table b = load(base, &cols), c = load(cur, &cols);
    double a1 = 1.0 - pow(1.0 - a.alpha, 1.0 / b.n);
    struct text_out t;
    FILE *f = text_out_open(&t);
    if (!f) opts_fail(prog, "out of memory");
    fprintf(f, "check_stats: %s vs baseline %s: alpha = %g family-wise, Sidak per row %.3g over %d rows, %s\n\n", cur,
            base, a.alpha, a1, b.n, a.count ? "Welch t" : "normal z");
    fprintf(f, "| %s | baseline | current | z | p | verdict |\n| --- | ---: | ---: | ---: | ---: | --- |\n",
            a.keyarg ? a.keyarg : keys[0]);
    int fails = compare(f, &b, &c, a.count != NULL, a1);
    fprintf(f, "\n%s: %d of %d rows differ significantly\n", fails ? "FAIL" : "PASS", fails, b.n);
    fflush(f);
    fputs(t.buf, stdout);
    char err[4352];
    bool ok = !a.out || text_out_commit(&t, a.out, err, sizeof err);
    text_out_free(&t);
    stats_table_free(&b);
    stats_table_free(&c);
    if (!ok) die(DIE_USAGE, prog, "%s", err); /* 2, as 1 means the statistics differ */
    return fails ? 1 : 0;
}
