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
#include "common/opts.h"
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

int main(int argc, char **argv)
{
    const char *keyarg = NULL, *mean, *se, *count = NULL, *out = NULL;
    double alpha;
    struct files fl = {.n = 0};
    const struct opt opts[] = {
        {"--key", OPT_STRING, OPT_DST(keyarg), .arg = "COLS",
         .help = "comma-separated key columns matching rows (default: first column)"},
        {"--mean", OPT_STRING, OPT_DST(mean), .arg = "COL", .help = "column with the mean", .def = "mean"},
        {"--se", OPT_STRING, OPT_DST(se), .arg = "COL", .help = "column with its standard error", .def = "se"},
        {"--count", OPT_STRING, OPT_DST(count), .arg = "COL",
         .help =
             "column with the number of runs behind the mean: p-values from Student's t with Welch-Satterthwaite df "
             "instead of the normal distribution"},
        {"--alpha", OPT_DOUBLE, OPT_DST(alpha), .arg = "A", .lo = DBL_TRUE_MIN, .hi = 1 - 0x1p-53,
         .expect = "a number in (0, 1)", .help = "family-wise significance level, Sidak-corrected over rows",
         .def = "0.01"},
        {"--out", OPT_STRING, OPT_DST(out), .arg = "FILE", .help = "also write the verdict table (Markdown) to FILE"},
        {0}};
    opts_parse(
        &(struct opts_spec){.prog = prog,
                            .usage = "usage: check_stats [options] BASELINE.csv CURRENT.csv\n",
                            .about = "Compares per-row means (with standard errors) of CURRENT against BASELINE.\n",
                            .tail = "exit status: 0 consistent, 1 significant difference or missing row, 2 bad input\n",
                            .opts = opts,
                            .positional = file_arg,
                            .ctx = &fl},
        argc, argv);
    if (fl.n != 2) opts_fail(prog, "expected BASELINE.csv CURRENT.csv (see --help)");
    const char **files = fl.name;

    char keys[STATS_MAXKEY][STATS_NAME];
    struct stats_cols cols = {.mean = mean, .se = se, .count = count};
    if (keyarg) {
        const char *p = keyarg;
        while (*p) {
            size_t l = strcspn(p, ",");
            if (l == 0 || l >= STATS_NAME || cols.nkeys == STATS_MAXKEY)
                opts_fail(prog, "--key: bad column list '%s'", keyarg);
            memcpy(keys[cols.nkeys], p, l);
            keys[cols.nkeys][l] = 0;
            cols.key[cols.nkeys] = keys[cols.nkeys];
            cols.nkeys++;
            p += l;
            if (*p) p++;
        }
    } else {
        /* default: the baseline's first column */
        FILE *f = fopen(files[0], "r");
        if (!f) opts_fail(prog, "%s: %s", files[0], strerror(errno));
        char err[512];
        bool ok = stats_csv_first_column(f, files[0], keys[0], err, sizeof err);
        fclose(f);
        if (!ok) opts_fail(prog, "%s", err);
        cols.key[cols.nkeys++] = keys[0];
    }

    struct stats_table b = load(files[0], &cols);
    struct stats_table c = load(files[1], &cols);
    double a1 = 1.0 - pow(1.0 - alpha, 1.0 / b.n);
    int fails = 0;
    size_t cap = 4096, len = 0;
    char *txt = malloc(cap);
    if (!txt) opts_fail(prog, "out of memory");
#define OUT(...)                                                                                                       \
    do {                                                                                                               \
        int n_ = snprintf(NULL, 0, __VA_ARGS__);                                                                       \
        while (len + (size_t)n_ + 1 > cap) {                                                                           \
            cap *= 2;                                                                                                  \
            txt = realloc(txt, cap);                                                                                   \
            if (!txt) opts_fail(prog, "out of memory");                                                                \
        }                                                                                                              \
        snprintf(txt + len, cap - len, __VA_ARGS__);                                                                   \
        len += (size_t)n_;                                                                                             \
    } while (0)
    OUT("check_stats: %s vs baseline %s: alpha = %g family-wise, Sidak per row %.3g over %d rows, %s\n\n", files[1],
        files[0], alpha, a1, b.n, count ? "Welch t" : "normal z");
    OUT("| %s | baseline | current | z | p | verdict |\n| --- | ---: | ---: | ---: | ---: | --- |\n",
        keyarg ? keyarg : keys[0]);
    for (int i = 0; i < b.n; i++) {
        const struct stats_row *rb = &b.rows[i], *rc = NULL;
        for (int j = 0; j < c.n; j++)
            if (!strcmp(c.rows[j].key, rb->key)) rc = &c.rows[j];
        if (!rc) {
            OUT("| %s | %.4g ± %.2g | missing | | | FAIL |\n", rb->key, rb->mean, rb->se);
            fails++;
            continue;
        }
        double s = sqrt(rb->se * rb->se + rc->se * rc->se), d = rc->mean - rb->mean;
        double z = s > 0 ? d / s : (d == 0 ? 0 : copysign(INFINITY, d)), p;
        if (!isfinite(z))
            p = 0;
        else if (count) {
            double vb = rb->se * rb->se, vc = rc->se * rc->se;
            double den = vb * vb / (rb->count - 1) + vc * vc / (rc->count - 1);
            double df = den > 0 ? (vb + vc) * (vb + vc) / den : 1e9;
            p = 2 * gsl_cdf_tdist_Q(fabs(z), df);
        } else
            p = 2 * gsl_cdf_ugaussian_Q(fabs(z));
        int f = p < a1;
        fails += f;
        OUT("| %s | %.4g ± %.2g | %.4g ± %.2g | %+.2f | %.2g | %s |\n", rb->key, rb->mean, rb->se, rc->mean, rc->se, z,
            p, f ? "FAIL" : "ok");
    }
    OUT("\n%s: %d of %d rows differ significantly\n", fails ? "FAIL" : "PASS", fails, b.n);
    fputs(txt, stdout);
    char err[4352];
    if (out && !write_text_atomic(out, txt, err, sizeof err)) {
        fprintf(stderr, "check_stats: %s\n", err); /* 2, as 1 means the statistics differ */
        return 2;
    }
    free(txt);
    stats_table_free(&b);
    stats_table_free(&c);
    return fails ? 1 : 0;
}
