/* Claims files (claims.h). */
#include "common/claims.h"
#include "base/util.h"
#include "common/csv_meta.h"
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

void claims_begin(struct claims *cl, const char *scale, const char *command, const char *title, ...)
{
    memset(cl, 0, sizeof *cl);
    cl->scale = scale;
    cl->command = command;
    cl->c = open_memstream(&cl->csv, &cl->clen);
    cl->m = open_memstream(&cl->md, &cl->mlen);
    char head[1024];
    va_list ap;
    va_start(ap, title);
    vsnprintf(head, sizeof head, title, ap);
    va_end(ap);
    csv_meta(cl->c, NULL, "%s", head);
    csv_meta_commit(cl->c);
    csv_meta(cl->c, NULL,
             "z in the claimed direction over seeds; holds: z >= 2 (against every other method, or inside "
             "a similarity margin); contradicted: z <= -2; seeds_needed: per method, for |z_min| = 2");
    fprintf(cl->c,
            "id,source,claim,statistic,method,value,se,z_by_method,z_min,verdict,seeds_needed,scale,command,mixing\n");
    fprintf(cl->m,
            "%s (mean ± standard error over seeds; z in the claimed direction; holds: z ≥ 2, contradicted: "
            "z ≤ −2):\n\n| id | claim | statistic | value | against (z) | verdict |\n| --- | --- | --- | ---: | --- | "
            "--- |\n",
            head);
}

/* A text field of the CSV: its commas become semicolons, so that every row splits on commas alone. */
static const char *field(const char *s, char *buf, size_t n)
{
    snprintf(buf, n, "%s", s);
    for (char *c = buf; *c; c++)
        if (*c == ',' || *c == '\n') *c = ';';
    return buf;
}

void claims_versus(const char *const *names, const double *mean, const double *se, const double *z, int k, char *versus,
                   size_t vlen, char *versus_md, size_t mlen)
{
    versus[0] = versus_md[0] = 0;
    for (int i = 0; i < k; i++) {
        if (isnan(z[i])) continue;
        size_t a = strlen(versus), b = strlen(versus_md);
        snprintf(versus + a, vlen - a, "%s%s=%.2f", a ? ";" : "", names[i], z[i]);
        snprintf(versus_md + b, mlen - b, "%s%s %.4g ± %.2g (z = %.1f)", b ? "; " : "", names[i], mean[i], se[i], z[i]);
    }
}

/* A text cell of the Markdown table: its pipes escaped, so that a claim such as "|j - i| is small"
 * keeps the table's columns. */
static const char *md_cell(const char *s, char *buf, size_t n)
{
    size_t k = 0;
    for (; *s && k + 2 < n; s++) {
        if (*s == '|') buf[k++] = '\\';
        buf[k++] = *s;
    }
    buf[k] = 0;
    return buf;
}

void claims_row(struct claims *cl, const char *id, const char *source, const char *claim, const char *statistic,
                const char *method, double value, double se, const char *versus, const char *versus_md,
                const struct verdict *v)
{
    char need[96] = "";
    if (!strcmp(v->word, "undecided") && v->seeds_needed > 0)
        snprintf(need, sizeof need, "; %ld seeds would decide it (toward %s)", v->seeds_needed,
                 v->zmin > 0 ? "holds" : "contradicted");
    else if (!strcmp(v->word, "undecided"))
        snprintf(need, sizeof need, "; no effect seen");
    char f[8][512];
    const char *flag = cl->flag ? cl->flag : "";
    fprintf(cl->c, "%s,%s,%s,%s,%s,%.6g,%.3g,%s,%.3f,%s,%ld,%s,%s,%s\n", field(id, f[6], 512), field(source, f[0], 512),
            field(claim, f[1], 512), field(statistic, f[2], 512), field(method, f[3], 512), value, se,
            field(versus, f[4], 512), v->zmin, v->word, v->seeds_needed, field(cl->scale, f[5], 512), cl->command,
            field(flag, f[7], 512));
    char m[3][1024];
    fprintf(cl->m, "| %s | %s | %s | %s %.4g ± %.2g | %s | **%s**%s%s%s |\n", id, md_cell(claim, m[0], sizeof m[0]),
            md_cell(statistic, m[1], sizeof m[1]), method, value, se, md_cell(versus_md, m[2], sizeof m[2]), v->word,
            need, *flag ? "; ⚠ " : "", flag);
}

void claims_row_against(struct claims *cl, const char *id, const char *source, const char *claim, const char *statistic,
                        const char *method, double value, double se, const struct verdict *v, const char *against,
                        const char *against_md, ...)
{
    char versus[256], md[512];
    snprintf(versus, sizeof versus, "%s=%.2f", against, v->zmin);
    va_list ap;
    va_start(ap, against_md);
    int n = vsnprintf(md, sizeof md, against_md, ap);
    va_end(ap);
    if (n >= 0 && (size_t)n < sizeof md) snprintf(md + n, sizeof md - (size_t)n, " (z = %.1f)", v->zmin);
    claims_row(cl, id, source, claim, statistic, method, value, se, versus, md, v);
}

char *claims_finish(struct claims *cl, const char *dir, char *err, size_t errlen)
{
    fclose(cl->c);
    fclose(cl->m);
    char path[4200];
    snprintf(path, sizeof path, "%.4000s/claims.csv", dir);
    bool ok = write_text_atomic(path, cl->csv, err, errlen);
    snprintf(path, sizeof path, "%.4000s/claims.md", dir);
    ok = ok && write_text_atomic(path, cl->md, err, errlen);
    free(cl->csv);
    if (ok) return cl->md;
    free(cl->md);
    return NULL;
}

void claims_finish_print(struct claims *cl, const char *dir)
{
    char err[1024];
    char *text = claims_finish(cl, dir, err, sizeof err);
    if (!text) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
    fputs(text, stderr);
    free(text);
}
