/* A figure's table of its runs' mixing diagnostics (mixing_runs.h). */
#include "common/mixing_runs.h"
#include "stats/mixing.h"
#include <stdio.h>

FILE *mixing_runs_open(struct mixing_runs *m, const char *prog, const char *name)
{
    m->prog = prog;
    m->name = name;
    m->started = false;
    return text_out_open(&m->out);
}

void mixing_runs_add(struct mixing_runs *m, const char *run, const struct mlt_result *r, double seconds)
{
    struct mixing_row rows[MAX_PATH_LENGTH + 2];
    int n = mixing_rows(r->trace, r->ntrace, rows, MAX_PATH_LENGTH + 2);
    if (m->out.f) {
        if (!m->started) mixing_runs_header(m->out.f); /* after the caller's metadata lines */
        m->started = true;
        mixing_write_run(m->out.f, run, rows, n, seconds);
    }
    char warn[1024];
    if (mixing_warning_line(rows, n, warn, sizeof warn))
        fprintf(stderr, "%s: warning: the chains of %s mix poorly: %s; see %s\n", m->prog, run, warn, m->name);
}

bool mixing_runs_save(struct mixing_runs *m, const char *dir, char *err, size_t errlen)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, m->name);
    if (!text_out_save(&m->out, path, err, errlen)) return false;
    fprintf(stderr, "%s: wrote %s\n", m->prog, path);
    return true;
}
