/* bin/ch6_equal's method list (ch6_equal.h): each item is a bin/render method, or NAME=ARGS with
 * bin/render's own options; a method bin/render does not accept is skipped and named. */
#include "base/util.h"
#include "ch6/ch6_equal.h"
#include "common/opts.h"
#include "common/proc.h"
#include <stdio.h>
#include <string.h>

/* Cuts s at spaces into argv (in place: s must live as long as argv). */
static void split_args(char *s, char **argv, int *argc, int cap)
{
    for (char *tok = strtok(s, " "); tok; tok = strtok(NULL, " "))
        if (*argc < cap) argv[(*argc)++] = tok;
}

/* render [method args] --help exits 0 when it accepts them (in a child: --help exits) */
static bool probe(const struct ch6_equal *e, const struct ch6_method *m)
{
    char *pv[CH6_MAX_ARGS + 4];
    int pc = 0;
    pv[pc++] = (char *)e->render;
    for (int k = 0; k < m->argc; k++)
        pv[pc++] = m->argv[k];
    pv[pc++] = "--help";
    pv[pc] = NULL;
    return proc_probe(&e->renderer, pv) == 0;
}

void ch6_methods_parse(struct ch6_equal *e, const char *methods)
{
    e->methods_buf = xstrdup(methods);
    char *save = NULL;
    for (char *item = strtok_r(e->methods_buf, ",", &save); item; item = strtok_r(NULL, ",", &save)) {
        if (e->nm == CH6_MAX_METHODS) opts_fail(e->prog, "--methods: at most %d", CH6_MAX_METHODS);
        struct ch6_method *m = &e->ms[e->nm++];
        memset(m, 0, sizeof *m);
        char *eq = strchr(item, '=');
        if (eq) {
            *eq = 0;
            split_args(eq + 1, m->argv, &m->argc, CH6_MAX_ARGS - 24);
        } else {
            m->argv[m->argc++] = "--method";
            m->argv[m->argc++] = item;
        }
        snprintf(m->name, sizeof m->name, "%s", item);
        if (!*m->name || m->argc == 0) opts_fail(e->prog, "--methods: empty item in '%s'", methods);
        m->available = probe(e, m);
        if (!m->available)
            fprintf(stderr, "%s: %s: %s does not accept '%s'; skipped\n", e->prog, m->name, e->render,
                    eq ? eq + 1 : item);
    }
    memcpy(e->extra_buf, e->extra_s, sizeof e->extra_s);
    split_args(e->extra_buf, e->extra_argv, &e->extra_c, CH6_MAX_ARGS - 24);
}
