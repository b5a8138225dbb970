/* A tool's tables written together (table_set.h). */
#include "common/table_set.h"

void table_set_open(struct table_set *ts, int n, const char *const *names, const struct column *const *cols,
                    void (*meta)(FILE *f, const void *ctx), const void *ctx)
{
    ts->n = n;
    for (int i = 0; i < n; i++) {
        ts->names[i] = names[i];
        FILE *f = table_open(&ts->t[i], cols[i]);
        if (meta && f) meta(f, ctx);
    }
}

FILE *table_set_open_one(struct table_set *ts, const char *name, const struct column *cols)
{
    table_set_open(ts, 1, &name, &cols, NULL, NULL);
    return ts->t[0].out.f;
}

bool table_set_save(struct table_set *ts, const char *prog, const char *dir, char *err, size_t errlen)
{
    bool ok = true;
    char path[4096];
    for (int i = 0; i < ts->n; i++) {
        snprintf(path, sizeof path, "%s/%s", dir, ts->names[i]);
        if (ok)
            ok = table_save(&ts->t[i], path, err, errlen);
        else
            text_out_free(&ts->t[i].out);
    }
    if (!ok) return false;
    fprintf(stderr, "%s: wrote", prog);
    for (int i = 0; i < ts->n; i++)
        fprintf(stderr, "%s %s/%s", i ? "," : "", dir, ts->names[i]);
    fputc('\n', stderr);
    return true;
}

void table_columns(struct column *c, int n, const char *const *names, enum col_type type, size_t off, size_t stride,
                   const char *fmt)
{
    for (int i = 0; i < n; i++)
        c[i] = (struct column){.name = names[i], .fmt = fmt, .type = type, .off = off + (size_t)i * stride};
}
