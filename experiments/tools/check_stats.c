/* Generic statistical regression check: compares per-row means with standard errors in a current
 * CSV against a committed baseline CSV. Rows are matched by key columns; for each row
 *   z = (mean - mean_b) / sqrt(se^2 + se_b^2),
 * two-sided p-value from the normal distribution, or, when a count column is given (number of
 * independent runs behind each mean), from Student's t with Welch-Satterthwaite degrees of freedom.
 * A row differs significantly when p < alpha_1 = 1 - (1 - alpha)^(1/m) (Sidak over the m compared
 * rows). A baseline row missing from the current file is a failure. Prints a per-row verdict table
 * (Markdown). Exit status: 0 no significant difference, 1 some difference or missing row, 2 bad input.
 * CSV: a header row, comma-separated fields without quoting, lines starting with '#' ignored. */
#include "common/opts.h"
#include <errno.h>
#include <float.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXCOL 64
#define MAXKEY 8
#define LINE 4096

static const char *const prog = "check_stats";

struct row {
    char key[256];
    double mean, se, count;
};

struct table {
    struct row *rows;
    int n;
};

static int split(char *line, char **f)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = 0;
    char *p = line;
    for (;;) {
        if (n == MAXCOL) return -1;
        f[n++] = p;
        char *c = strchr(p, ',');
        if (!c) break;
        *c = 0;
        p = c + 1;
    }
    return n;
}

static int find_col(char **hdr, int n, const char *name, const char *file)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(hdr[i], name)) return i;
    opts_fail(prog, "%s: no column '%s' in the header", file, name);
    return -1;
}

static double num(const char *s, const char *file, int line, const char *col)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !isfinite(v)) opts_fail(prog, "%s:%d: column '%s': expected a number, got '%s'", file, line, col, s);
    return v;
}

static struct table load(const char *file, char keys[MAXKEY][64], int nkeys, const char *mean, const char *se,
                         const char *count)
{
    FILE *f = fopen(file, "r");
    if (!f) opts_fail(prog, "%s: %s", file, strerror(errno));
    char line[LINE], *fld[MAXCOL], *hdr[MAXCOL], hline[LINE];
    int nh = -1, ln = 0, kc[MAXKEY], mc = -1, sc = -1, cc = -1;
    struct table t = {NULL, 0};
    int cap = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        if (line[0] == '#' || line[strspn(line, " \t\r\n")] == 0) continue;
        if (nh < 0) {
            strcpy(hline, line);
            nh = split(hline, hdr);
            if (nh < 0) opts_fail(prog, "%s:%d: too many columns", file, ln);
            for (int k = 0; k < nkeys; k++) kc[k] = find_col(hdr, nh, keys[k], file);
            mc = find_col(hdr, nh, mean, file);
            sc = find_col(hdr, nh, se, file);
            if (count) cc = find_col(hdr, nh, count, file);
            continue;
        }
        int n = split(line, fld);
        if (n != nh) opts_fail(prog, "%s:%d: %d fields, header has %d", file, ln, n, nh);
        if (t.n == cap) {
            cap = cap ? 2 * cap : 32;
            t.rows = realloc(t.rows, sizeof *t.rows * (size_t)cap);
            if (!t.rows) opts_fail(prog, "out of memory");
        }
        struct row *r = &t.rows[t.n++];
        r->key[0] = 0;
        for (int k = 0; k < nkeys; k++) {
            if (strlen(r->key) + strlen(fld[kc[k]]) + 2 >= sizeof r->key) opts_fail(prog, "%s:%d: key too long", file, ln);
            if (k) strcat(r->key, ",");
            strcat(r->key, fld[kc[k]]);
        }
        for (int q = 0; q < t.n - 1; q++)
            if (!strcmp(t.rows[q].key, r->key)) opts_fail(prog, "%s:%d: duplicate key '%s'", file, ln, r->key);
        r->mean = num(fld[mc], file, ln, mean);
        r->se = num(fld[sc], file, ln, se);
        if (r->se < 0) opts_fail(prog, "%s:%d: negative standard error", file, ln);
        r->count = count ? num(fld[cc], file, ln, count) : 0;
        if (count && r->count < 2) opts_fail(prog, "%s:%d: column '%s' must be >= 2 for a t test", file, ln, count);
    }
    fclose(f);
    if (nh < 0) opts_fail(prog, "%s: no header row", file);
    if (t.n == 0) opts_fail(prog, "%s: no data rows", file);
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
        {"--key", OPT_STRING, OPT_DST(keyarg), .arg = "COLS", .help = "comma-separated key columns matching rows (default: first column)"},
        {"--mean", OPT_STRING, OPT_DST(mean), .arg = "COL", .help = "column with the mean", .def = "mean"},
        {"--se", OPT_STRING, OPT_DST(se), .arg = "COL", .help = "column with its standard error", .def = "se"},
        {"--count", OPT_STRING, OPT_DST(count), .arg = "COL",
         .help = "column with the number of runs behind the mean: p-values from Student's t with Welch-Satterthwaite df "
                 "instead of the normal distribution"},
        {"--alpha", OPT_DOUBLE, OPT_DST(alpha), .arg = "A", .lo = DBL_TRUE_MIN, .hi = 1 - 0x1p-53, .expect = "a number in (0, 1)",
         .help = "family-wise significance level, Sidak-corrected over rows", .def = "0.01"},
        {"--out", OPT_STRING, OPT_DST(out), .arg = "FILE", .help = "also write the verdict table (Markdown) to FILE"},
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog, .usage = "usage: check_stats [options] BASELINE.csv CURRENT.csv\n",
                                   .about = "Compares per-row means (with standard errors) of CURRENT against BASELINE.\n",
                                   .tail = "exit status: 0 consistent, 1 significant difference or missing row, 2 bad input\n",
                                   .opts = opts, .positional = file_arg, .ctx = &fl},
               argc, argv);
    if (fl.n != 2) opts_fail(prog, "expected BASELINE.csv CURRENT.csv (see --help)");
    const char **files = fl.name;

    char keys[MAXKEY][64];
    int nkeys = 0;
    if (keyarg) {
        const char *p = keyarg;
        while (*p) {
            size_t l = strcspn(p, ",");
            if (l == 0 || l >= 64 || nkeys == MAXKEY) opts_fail(prog, "--key: bad column list '%s'", keyarg);
            memcpy(keys[nkeys], p, l);
            keys[nkeys++][l] = 0;
            p += l;
            if (*p) p++;
        }
    } else {
        /* default: the baseline's first column */
        FILE *f = fopen(files[0], "r");
        if (!f) opts_fail(prog, "%s: %s", files[0], strerror(errno));
        char line[LINE];
        while (fgets(line, sizeof line, f) && (line[0] == '#')) {}
        fclose(f);
        size_t l = strcspn(line, ",\r\n");
        if (l == 0 || l >= 64) opts_fail(prog, "%s: cannot read the first column name", files[0]);
        memcpy(keys[0], line, l);
        keys[0][l] = 0;
        nkeys = 1;
    }

    struct table b = load(files[0], keys, nkeys, mean, se, count);
    struct table c = load(files[1], keys, nkeys, mean, se, count);
    double a1 = 1.0 - pow(1.0 - alpha, 1.0 / b.n);
    int fails = 0;
    size_t cap = 4096, len = 0;
    char *txt = malloc(cap);
    if (!txt) opts_fail(prog, "out of memory");
#define OUT(...)                                                                                                   \
    do {                                                                                                           \
        int n_ = snprintf(NULL, 0, __VA_ARGS__);                                                                   \
        while (len + (size_t)n_ + 1 > cap) {                                                                       \
            cap *= 2;                                                                                              \
            txt = realloc(txt, cap);                                                                               \
            if (!txt) opts_fail(prog, "out of memory");                                                                        \
        }                                                                                                          \
        snprintf(txt + len, cap - len, __VA_ARGS__);                                                               \
        len += (size_t)n_;                                                                                         \
    } while (0)
    OUT("check_stats: %s vs baseline %s: alpha = %g family-wise, Sidak per row %.3g over %d rows, %s\n\n", files[1],
        files[0], alpha, a1, b.n, count ? "Welch t" : "normal z");
    OUT("| %s | baseline | current | z | p | verdict |\n| --- | ---: | ---: | ---: | ---: | --- |\n", keyarg ? keyarg : keys[0]);
    for (int i = 0; i < b.n; i++) {
        const struct row *rb = &b.rows[i], *rc = NULL;
        for (int j = 0; j < c.n; j++)
            if (!strcmp(c.rows[j].key, rb->key)) rc = &c.rows[j];
        if (!rc) {
            OUT("| %s | %.4g ± %.2g | missing | | | FAIL |\n", rb->key, rb->mean, rb->se);
            fails++;
            continue;
        }
        double s = sqrt(rb->se * rb->se + rc->se * rc->se), d = rc->mean - rb->mean;
        double z = s > 0 ? d / s : (d == 0 ? 0 : copysign(INFINITY, d)), p;
        if (!isfinite(z)) p = 0;
        else if (count) {
            double vb = rb->se * rb->se, vc = rc->se * rc->se;
            double den = vb * vb / (rb->count - 1) + vc * vc / (rc->count - 1);
            double df = den > 0 ? (vb + vc) * (vb + vc) / den : 1e9;
            p = 2 * gsl_cdf_tdist_Q(fabs(z), df);
        } else
            p = 2 * gsl_cdf_ugaussian_Q(fabs(z));
        int f = p < a1;
        fails += f;
        OUT("| %s | %.4g ± %.2g | %.4g ± %.2g | %+.2f | %.2g | %s |\n", rb->key, rb->mean, rb->se, rc->mean, rc->se, z, p,
            f ? "FAIL" : "ok");
    }
    OUT("\n%s: %d of %d rows differ significantly\n", fails ? "FAIL" : "PASS", fails, b.n);
    fputs(txt, stdout);
    if (out) {
        char tmp[4096];
        snprintf(tmp, sizeof tmp, "%s.tmp", out);
        FILE *f = fopen(tmp, "w");
        if (!f || fwrite(txt, 1, len, f) != len || fclose(f) != 0 || rename(tmp, out) != 0) {
            fprintf(stderr, "check_stats: cannot write %s\n", out);
            return 2;
        }
    }
    free(txt);
    free(b.rows);
    free(c.rows);
    return fails ? 1 : 0;
}
