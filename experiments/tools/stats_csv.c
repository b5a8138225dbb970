/* Statistics CSV reader; see stats_csv.h. */
#include "tools/stats_csv.h"
#include "base/util.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static bool fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static bool fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    if (errlen) str_sanitize(err);
    return false;
}

/* The next line that is neither a comment nor blank, without its line end; false at the end of
 * the file or (with a message) on a line too long for the buffer, which would otherwise be read as
 * two. */
static bool next_line(FILE *f, const char *name, char line[STATS_LINE], int *ln, bool *bad, char *err, size_t errlen)
{
    while (fgets(line, STATS_LINE, f)) {
        ++*ln;
        size_t l = strlen(line);
        if (l == STATS_LINE - 1 && line[l - 1] != '\n' && !feof(f)) {
            *bad = true;
            return fail(err, errlen, "%s:%d: line longer than %d characters", name, *ln, STATS_LINE - 2);
        }
        line[strcspn(line, "\r\n")] = 0;
        if (line[0] == '#' || line[strspn(line, " \t")] == 0) continue;
        return true;
    }
    return false;
}

static int split(char *line, char **f)
{
    int n = 0;
    for (char *p = line;;) {
        if (n == STATS_MAXCOL) return -1;
        f[n++] = p;
        char *c = strchr(p, ',');
        if (!c) break;
        *c = 0;
        p = c + 1;
    }
    return n;
}

static int find_col(char **hdr, int n, const char *col)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(hdr[i], col)) return i;
    return -1;
}

static bool num(const char *s, double *v)
{
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return !errno && end != s && !*end && isfinite(*v);
}

void stats_table_free(struct stats_table *t)
{
    free(t->rows);
    t->rows = NULL;
    t->n = 0;
}

bool stats_csv_first_column(FILE *f, const char *name, char out[STATS_NAME], char *err, size_t errlen)
{
    char line[STATS_LINE];
    int ln = 0;
    bool bad = false;
    if (!next_line(f, name, line, &ln, &bad, err, errlen))
        return bad ? false : fail(err, errlen, "%s: no header row", name);
    size_t l = strcspn(line, ",");
    if (l == 0 || l >= STATS_NAME) return fail(err, errlen, "%s:%d: cannot read the first column name", name, ln);
    memcpy(out, line, l);
    out[l] = 0;
    return true;
}

/* The header's column of each wanted name: idx[0..nkeys) keys, then mean, se, count (-1 if none). */
static bool header(char *line, const char *name, int ln, const struct stats_cols *cols, int *nh, int *idx, char *err,
                   size_t errlen)
{
    char *hdr[STATS_MAXCOL];
    *nh = split(line, hdr);
    if (*nh < 0) return fail(err, errlen, "%s:%d: more than %d columns", name, ln, STATS_MAXCOL);
    const char *want[STATS_MAXKEY + 3];
    int nw = 0;
    for (int k = 0; k < cols->nkeys; k++)
        want[nw++] = cols->key[k];
    want[nw++] = cols->mean;
    want[nw++] = cols->se;
    want[nw++] = cols->count;
    for (int i = 0; i < nw; i++) {
        idx[i] = want[i] ? find_col(hdr, *nh, want[i]) : -1;
        if (want[i] && idx[i] < 0) return fail(err, errlen, "%s: no column '%s' in the header", name, want[i]);
    }
    return true;
}

static bool row(char **fld, const char *name, int ln, const struct stats_cols *cols, const int *idx,
                struct stats_table *t, char *err, size_t errlen)
{
    struct stats_row *r = &t->rows[t->n];
    r->key[0] = 0;
    for (int k = 0; k < cols->nkeys; k++) {
        const char *v = fld[idx[k]];
        if (strlen(r->key) + strlen(v) + 2 > sizeof r->key) return fail(err, errlen, "%s:%d: key too long", name, ln);
        if (k) strcat(r->key, ",");
        strcat(r->key, v);
    }
    for (int q = 0; q < t->n; q++)
        if (!strcmp(t->rows[q].key, r->key)) return fail(err, errlen, "%s:%d: duplicate key '%s'", name, ln, r->key);
    const char *col[3] = {cols->mean, cols->se, cols->count};
    double *dst[3] = {&r->mean, &r->se, &r->count};
    r->count = 0;
    for (int i = 0; i < 3; i++)
        if (col[i] && !num(fld[idx[cols->nkeys + i]], dst[i]))
            return fail(err, errlen, "%s:%d: column '%s': expected a number, got '%.40s'", name, ln, col[i],
                        fld[idx[cols->nkeys + i]]);
    if (r->se < 0) return fail(err, errlen, "%s:%d: negative standard error", name, ln);
    if (cols->count && r->count < 2)
        return fail(err, errlen, "%s:%d: column '%s' must be >= 2 for a t test", name, ln, cols->count);
    t->n++;
    return true;
}

bool stats_csv_read(FILE *f, const char *name, const struct stats_cols *cols, struct stats_table *t, char *err,
                    size_t errlen)
{
    *t = (struct stats_table){NULL, 0};
    char line[STATS_LINE], *fld[STATS_MAXCOL];
    int idx[STATS_MAXKEY + 3], nh = -1, ln = 0, cap = 0;
    bool bad = false, ok = true;
    while (ok && next_line(f, name, line, &ln, &bad, err, errlen)) {
        if (nh < 0) {
            ok = header(line, name, ln, cols, &nh, idx, err, errlen);
            continue;
        }
        int n = split(line, fld);
        if (n != nh) {
            ok = fail(err, errlen, "%s:%d: %d fields, header has %d", name, ln, n < 0 ? STATS_MAXCOL + 1 : n, nh);
            break;
        }
        if (t->n == cap) {
            cap = cap ? 2 * cap : 32;
            t->rows = xrealloc(t->rows, sizeof *t->rows * (size_t)cap);
        }
        ok = row(fld, name, ln, cols, idx, t, err, errlen);
    }
    if (ok && bad) ok = false;
    if (ok && nh < 0) ok = fail(err, errlen, "%s: no header row", name);
    if (ok && t->n == 0) ok = fail(err, errlen, "%s: no data rows", name);
    if (!ok) stats_table_free(t);
    return ok;
}
