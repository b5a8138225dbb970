/* CSV files read by column name and metadata key (csv_read.h). */
#include "common/csv_read.h"
#include "base/util.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The cells of s: cut at every comma into cells[0..cap-1] when cells is given (else only
 * counted); returns the count. */
static int split(char *s, char **cells, int cap)
{
    for (int n = 0;;) {
        char *p = strchr(s, ',');
        if (cells && n < cap) cells[n] = s;
        n++;
        if (!p) return n;
        if (cells) *p = 0;
        s = p + 1;
    }
}

static void add_meta(struct csv_file *c, char *line)
{
    char *k = line + 1;
    while (*k == ' ')
        k++;
    char *sp = strchr(k, ' ');
    if (sp) *sp = 0;
    c->meta_key = xrealloc(c->meta_key, sizeof(char *) * (size_t)(c->nmeta + 1));
    c->meta_val = xrealloc(c->meta_val, sizeof(char *) * (size_t)(c->nmeta + 1));
    c->meta_key[c->nmeta] = k;
    c->meta_val[c->nmeta++] = sp ? sp + 1 : k + strlen(k);
}

static bool add_row(struct csv_file *c, char *line, int lineno, char *err, size_t errlen)
{
    if (!c->head) {
        c->ncols = split(line, NULL, 0);
        c->head = xmalloc(sizeof(char *) * (size_t)c->ncols);
        split(line, c->head, c->ncols);
        return true;
    }
    c->cells = xrealloc(c->cells, sizeof(char *) * (size_t)(c->nrows + 1) * (size_t)c->ncols);
    int n = split(line, c->cells + (size_t)c->nrows * c->ncols, c->ncols);
    if (n != c->ncols) {
        snprintf(err, errlen, "%s:%d: %d cells, the header has %d", c->name, lineno, n, c->ncols);
        return false;
    }
    c->nrows++;
    return true;
}

struct csv_file *csv_parse(char *text, const char *name, char *err, size_t errlen)
{
    struct csv_file *c = xcalloc(1, sizeof *c);
    c->name = xstrdup(name);
    c->text = text;
    int lineno = 0;
    for (char *line = text, *next; line && *line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = 0;
        lineno++;
        size_t n = strlen(line);
        if (n && line[n - 1] == '\r') line[--n] = 0;
        if (line[0] == '#')
            add_meta(c, line);
        else if (n && !add_row(c, line, lineno, err, errlen)) {
            csv_free(c);
            return NULL;
        }
    }
    if (!c->head) {
        snprintf(err, errlen, "%s: no header row", name);
        csv_free(c);
        return NULL;
    }
    return c;
}

struct csv_file *csv_load(const char *path, char *err, size_t errlen)
{
    char *text = read_whole_file(path);
    if (!text) {
        snprintf(err, errlen, "cannot read %s", path);
        return NULL;
    }
    return csv_parse(text, path, err, errlen);
}

void csv_free(struct csv_file *c)
{
    if (!c) return;
    free(c->name);
    free(c->text);
    free(c->head);
    free(c->cells);
    free(c->meta_key);
    free(c->meta_val);
    free(c);
}

int csv_column(const struct csv_file *c, const char *name, char *err, size_t errlen)
{
    for (int i = 0; i < c->ncols; i++)
        if (!strcmp(c->head[i], name)) return i;
    snprintf(err, errlen, "%s: no column '%s'", c->name, name);
    return -1;
}

const char *csv_cell(const struct csv_file *c, int r, int col) { return c->cells[(size_t)r * c->ncols + col]; }

double csv_number(const struct csv_file *c, int r, int col)
{
    const char *s = csv_cell(c, r, col);
    char *end;
    double v = strtod(s, &end);
    return end == s ? NAN : v;
}

const char *csv_meta_text(const struct csv_file *c, const char *key)
{
    for (int i = 0; i < c->nmeta; i++)
        if (!strcmp(c->meta_key[i], key)) return c->meta_val[i];
    return NULL;
}

double csv_meta_number(const struct csv_file *c, const char *key)
{
    const char *v = csv_meta_text(c, key);
    return v ? strtod(v, NULL) : NAN;
}

bool csv_meta_require(const struct csv_file *c, const char *key, double *v, char *err, size_t errlen)
{
    const char *s = csv_meta_text(c, key);
    if (!s) {
        snprintf(err, errlen, "%s: no '# %s' line", c->name, key);
        return false;
    }
    *v = strtod(s, NULL);
    return true;
}
