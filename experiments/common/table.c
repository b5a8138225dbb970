/* Tables from one column list (table.h). */
#include "common/table.h"

void table_write_header(FILE *f, const struct column *cols)
{
    for (const struct column *c = cols; c->type != COL_END; c++)
        fprintf(f, c == cols ? "%s" : ",%s", c->name);
    fputc('\n', f);
}

static void write_cell(FILE *f, const struct column *c, const void *row)
{
    const char *at = (const char *)row + c->off, *fmt = c->fmt ? c->fmt : "%s";
    switch (c->type) {
    case COL_STR:
        fprintf(f, fmt, *(const char *const *)at);
        break;
    case COL_I:
        fprintf(f, fmt, *(const int *)at);
        break;
    case COL_L:
        fprintf(f, fmt, *(const long *)at);
        break;
    case COL_D:
        fprintf(f, fmt, *(const double *)at);
        break;
    case COL_GET:
        fprintf(f, fmt, c->get(row, c->arg));
        break;
    case COL_END:
        break;
    }
}

void table_write_row(FILE *f, const struct column *cols, const void *row)
{
    for (const struct column *c = cols; c->type != COL_END; c++) {
        if (c != cols) fputc(',', f);
        write_cell(f, c, row);
    }
    fputc('\n', f);
}

FILE *table_open(struct table *t, const struct column *cols)
{
    t->cols = cols;
    t->header_done = false;
    return text_out_open(&t->out);
}

void table_header(struct table *t)
{
    if (t->header_done || !t->out.f) return;
    table_write_header(t->out.f, t->cols);
    t->header_done = true;
}

void table_row(struct table *t, const void *row)
{
    table_header(t);
    if (t->out.f) table_write_row(t->out.f, t->cols, row);
}

bool table_save(struct table *t, const char *path, char *err, size_t errlen)
{
    table_header(t);
    return text_out_save(&t->out, path, err, errlen);
}
