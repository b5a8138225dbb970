/* bin/inverse_density's tables and claims (inv_report.h). */
#include "ch5/inv_report.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/table.h"
#include "common/text_out.h"
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

static const char *const kind_name[] = {"bsdf", "camera", "emitter", "path"};

struct row {
    const char *function, *kind, *reference, *chi_where, *ks_where, *rejected;
    long samples, failures, forward_draws, forward_failures, ks_n;
    double chi2, chi_p, chi_p_adj, ks_d, ks_p, ks_p_adj;
    int dof, chi_tests, ks_tests;
};

static const struct column cols[] = {COL_STRING(struct row, "function", function),
                                     COL_STRING(struct row, "kind", kind),
                                     COL_LONG(struct row, "samples", "%ld", samples),
                                     COL_LONG(struct row, "failures", "%ld", failures),
                                     COL_LONG(struct row, "forward_draws", "%ld", forward_draws),
                                     COL_LONG(struct row, "forward_failures", "%ld", forward_failures),
                                     COL_STRING(struct row, "reference", reference),
                                     COL_DOUBLE(struct row, "chi2", "%.4f", chi2),
                                     COL_INT(struct row, "dof", "%d", dof),
                                     COL_DOUBLE(struct row, "chi2_p", "%.4g", chi_p),
                                     COL_INT(struct row, "chi2_tests", "%d", chi_tests),
                                     COL_DOUBLE(struct row, "chi2_p_sidak", "%.4g", chi_p_adj),
                                     COL_STRING(struct row, "chi2_where", chi_where),
                                     COL_DOUBLE(struct row, "ks_d", "%.6f", ks_d),
                                     COL_LONG(struct row, "ks_n", "%ld", ks_n),
                                     COL_DOUBLE(struct row, "ks_p", "%.4g", ks_p),
                                     COL_INT(struct row, "ks_tests", "%d", ks_tests),
                                     COL_DOUBLE(struct row, "ks_p_sidak", "%.4g", ks_p_adj),
                                     COL_STRING(struct row, "ks_where", ks_where),
                                     COL_STRING(struct row, "rejected", rejected),
                                     {0}};

static struct row row_of(const struct inv_func *f, const struct inv_result *r, double each)
{
    const struct inv_gof *g = &r->g;
    bool chi = g->chi_tests && g->chi_p_adj < each, ks = g->ks_tests && g->ks_p_adj < each;
    return (struct row){f->name,
                        kind_name[f->kind],
                        r->uniform ? "uniform" : "forward",
                        g->chi_worst,
                        g->ks_worst,
                        chi && ks                    ? "chi2;ks"
                        : chi                        ? "chi2"
                        : ks                         ? "ks"
                        : g->chi_tests + g->ks_tests ? "no"
                                                     : "untested",
                        r->samples,
                        r->failures,
                        r->fwd_tries,
                        r->fwd_fails,
                        g->ks_n,
                        g->chi2,
                        g->chi_p,
                        g->chi_p_adj,
                        g->ks_d,
                        g->ks_p,
                        g->ks_p_adj,
                        g->chi_dof,
                        g->chi_tests,
                        g->ks_tests};
}

/* A comma-separated list with spaces instead: a metadata line holds no comma. */
static const char *spaced(const char *list, char *buf, size_t n)
{
    snprintf(buf, n, "%s", list);
    for (char *p = buf; *p; p++)
        if (*p == ',') *p = ' ';
    return buf;
}

static void meta(FILE *f, const struct inv_cfg *c, int tests, double each)
{
    csv_meta_head(f, "Thesis Eq. 5.3: inverted numbers of forward-sampled paths against forward numbers", "-",
                  c->scale);
    csv_meta(f, "samples", "%ld per pass (BSDF camera emitter); %ld (paths)", c->samples, c->path_samples);
    csv_meta(f, "seed", "%llu", (unsigned long long)c->seed);
    char a[512], b[512];
    csv_meta(f, "scenes", "BSDFs of %s; camera emitter paths of %s", spaced(c->bsdf_scenes, a, sizeof a),
             spaced(c->path_scenes, b, sizeof b));
    csv_meta(f, "tests",
             "chi2: %d bins per slot and %dx%d per slot pair of a block; KS per slot; p_sidak over "
             "each function's tests of that kind",
             INV_BINS_1D, INV_BINS_2D, INV_BINS_2D);
    csv_meta(f, "alpha", "%g family-wise over %d p-values: %.4g each (Sidak)", INV_ALPHA, tests, each);
    if (c->broken) csv_meta(f, "broken", "%s: first inverted number scaled by 0.99", c->broken);
}

static void save_or_die(const char *prog, struct text_out *t, const char *dir, const char *name)
{
    char path[4200], err[1024];
    snprintf(path, sizeof path, "%.4000s/%s", dir, name);
    if (!text_out_save(t, path, err, sizeof err)) die(DIE_RUNTIME, prog, "%s", err);
}

static void write_md(const struct inv_cfg *c, const struct row *rows, int n, int tests, double each)
{
    struct text_out t;
    FILE *m = text_out_open(&t);
    fprintf(m,
            "Thesis Eq. 5.3, inverted numbers against forward ones (scale %s, seed %llu; α = %g over %d p-values, "
            "%.3g each; p Šidák-adjusted within a function):\n\n| function | samples | failures | forward "
            "failures | against | χ² (dof) at | p | KS D at | p | rejected |\n| --- | ---: | ---: | ---: | --- | "
            "--- | ---: | --- | ---: | --- |\n",
            c->scale, (unsigned long long)c->seed, INV_ALPHA, tests, each);
    for (int i = 0; i < n; i++) {
        const struct row *w = &rows[i];
        fprintf(m, "| %s | %ld | %ld | %ld of %ld | %s | %.1f (%d) at %s | %.3g | %.4f at %s | %.3g | %s |\n",
                w->function, w->samples, w->failures, w->forward_failures, w->forward_draws, w->reference, w->chi2,
                w->dof, w->chi_where, w->chi_p_adj, w->ks_d, w->ks_where, w->ks_p_adj, w->rejected);
    }
    save_or_die(c->prog, &t, c->out, "inverse_density.md");
}

static void write_claims(const struct inv_cfg *c, const struct row *rows, int n, int tests)
{
    int worst = 0, rejected = 0, tested = 0;
    double pmin = 1;
    char names[512] = "";
    double each = inv_sidak_alpha(INV_ALPHA, tests);
    for (int i = 0; i < n; i++) {
        double p = fmin(rows[i].chi_tests ? rows[i].chi_p_adj : 1, rows[i].ks_tests ? rows[i].ks_p_adj : 1);
        if (p < pmin) pmin = p, worst = i;
        tested += strcmp(rows[i].rejected, "untested") != 0;
        if (strcmp(rows[i].rejected, "no") && strcmp(rows[i].rejected, "untested") && rejected++ < 4)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", rejected > 1 ? " " : "",
                     rows[i].function);
    }
    struct verdict v = verdict_no_rejection(pmin, INV_ALPHA, tests);
    struct claims cl;
    char command[96], vs[640], md[768];
    snprintf(command, sizeof command, "make inverse-density SCALE=%s", c->scale);
    claims_begin(&cl, c->scale, command, "Claim of thesis §5.1 (Eq. 5.3) over %d sampling functions with inverses", n);
    snprintf(vs, sizeof vs, "alpha_each=%.3g;rejected=%d;%s", each, rejected, names);
    snprintf(md, sizeof md, "level %.3g per p-value (α = %g over %d, Šidák); %d of %d tested functions reject%s%s",
             each, INV_ALPHA, tests, rejected, tested, rejected ? ": " : "", names);
    claims_row(&cl, "T21", "thesis §5.1 Eq. 5.3",
               "inverted numbers have the density of the forward numbers, for every inverse sampling function",
               "smallest p of chi-square (per slot; per slot pair) and KS (per slot) of the inverted numbers",
               rows[worst].function, pmin, NAN, vs, md, &v);
    claims_finish_print(&cl, c->out);
}

bool inv_report(const struct inv_cfg *c, const struct inv_func *f, const struct inv_result *r, int n)
{
    int tests = 0;
    for (int i = 0; i < n; i++)
        tests += (r[i].g.chi_tests > 0) + (r[i].g.ks_tests > 0);
    if (!tests) die(DIE_RUNTIME, c->prog, "no function had %d samples to test", INV_MIN_SAMPLES);
    double each = inv_sidak_alpha(INV_ALPHA, tests);
    struct row rows[n];
    struct table t;
    meta(table_open(&t, cols), c, tests, each);
    bool holds = true;
    for (int i = 0; i < n; i++) {
        rows[i] = row_of(&f[i], &r[i], each);
        holds &= !strcmp(rows[i].rejected, "no") || !strcmp(rows[i].rejected, "untested");
        table_row(&t, &rows[i]);
    }
    char path[4200], err[1024];
    snprintf(path, sizeof path, "%.4000s/inverse_density.csv", c->out);
    if (!table_save(&t, path, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
    write_md(c, rows, n, tests, each);
    write_claims(c, rows, n, tests);
    return holds;
}
