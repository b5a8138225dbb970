/* A chapter-4 figure's tables (ch4_tables.h). */
#include "ch4/ch4_tables.h"
#include "common/verdict.h"

void ch4_tables_open(struct ch4_tables *tb, int n, const char *const *names, const struct column *const *cols,
                     void (*meta)(FILE *f, const void *ctx), const void *ctx)
{
    tb->n = n;
    for (int i = 0; i < n; i++) {
        tb->names[i] = names[i];
        FILE *f = table_open(&tb->t[i], cols[i]);
        if (meta && f) meta(f, ctx);
    }
}

FILE *ch4_tables_open_one(struct ch4_tables *tb, const char *name, const struct column *cols)
{
    ch4_tables_open(tb, 1, &name, &cols, NULL, NULL);
    return tb->t[0].out.f;
}

bool ch4_tables_save(struct ch4_tables *tb, const char *prog, const char *dir, char *err, size_t errlen)
{
    bool ok = true;
    char path[4096];
    for (int i = 0; i < tb->n; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, tb->names[i]);
        if (ok)
            ok = table_save(&tb->t[i], path, err, errlen);
        else
            text_out_free(&tb->t[i].out);
    }
    if (!ok) return false;
    fprintf(stderr, "%s: wrote", prog);
    for (int i = 0; i < tb->n; i++)
        fprintf(stderr, "%s %s/%s", i ? "," : "", dir, tb->names[i]);
    fputc('\n', stderr);
    return true;
}

void ch4_stat_row_of(struct ch4_stat_row *row, const double *x, int seeds)
{
    row->seeds = seeds;
    mean_se(x, seeds, &row->mean, &row->se);
}

void ch4_columns(struct column *c, int n, const char *const *names, enum col_type type, size_t off, size_t stride,
                 const char *fmt)
{
    for (int i = 0; i < n; i++)
        c[i] = (struct column){.name = names[i], .fmt = fmt, .type = type, .off = off + (size_t)i * stride};
}
