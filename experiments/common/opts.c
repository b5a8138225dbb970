/* The option table parser and its --help (opts.h). */
#include "common/opts.h"
#include "base/util.h"
#include "common/die.h"
#include "common/outdir.h"
#include "io/oiio.h"
#include "path/scene_ready.h"
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *const opts_scales[] = {"quick", "paper", "full", NULL};

void opts_fail(const char *prog, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vdie(DIE_USAGE, prog, fmt, ap);
}

void opts_require_image_input(const char *prog)
{
    char err[1024];
    if (!oiio_module_present(err, sizeof err)) die(DIE_RUNTIME, prog, "%s", err);
}

const struct opt *opts_find(const struct opts_spec *s, const char *name)
{
    for (const struct opt *o = s->opts; o->type != OPT_END; o++)
        if (o->name && !strcmp(o->name, name)) return o;
    return NULL;
}

/* An integer into a destination of 1, 2, 4 or 8 bytes (bool, int, long, an enum). */
static void store_int(const struct opt *o, long v)
{
    switch (o->size) {
    case 1:
        *(uint8_t *)o->dst = (uint8_t)v;
        break;
    case 2:
        *(int16_t *)o->dst = (int16_t)v;
        break;
    case 4:
        *(int32_t *)o->dst = (int32_t)v;
        break;
    case 8:
        *(int64_t *)o->dst = (int64_t)v;
        break;
    default:
        ASSERT(!"an integer option's destination of 1, 2, 4 or 8 bytes");
    }
}

/* "a, b or c" */
static void choice_list(const char *const *c, char *buf, size_t n)
{
    buf[0] = 0;
    for (int i = 0; c[i]; i++) {
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "%s%s", i == 0 ? "" : c[i + 1] ? ", " : " or ", c[i]);
    }
}

static bool parse_long(const char *v, long *out, char **end)
{
    errno = 0;
    *out = strtol(v, end, 10);
    return !errno && *end != v;
}

/* Checks `v` and stores it where option o puts its value; exits 2 on a bad value. */
static void set_value(const char *prog, const struct opt *o, const char *v)
{
    const char *name = o->name;
    char expect[256], *end;
    switch (o->type) {
    case OPT_INT: {
        long x;
        if (!parse_long(v, &x, &end) || *end || x < (long)o->lo || x > (long)o->hi) {
            if (!o->expect) snprintf(expect, sizeof expect, "an integer in [%ld, %ld]", (long)o->lo, (long)o->hi);
            opts_fail(prog, "%s: expected %s, got '%s'", name, o->expect ? o->expect : expect, v);
        }
        store_int(o, x);
        break;
    }
    case OPT_U64: {
        errno = 0;
        unsigned long long x = strtoull(v, &end, 10);
        bool bounded = o->hi > 0;
        if (errno || end == v || *end || v[0] == '-' ||
            (bounded && (x < (unsigned long long)o->lo || x > (unsigned long long)o->hi))) {
            if (bounded)
                snprintf(expect, sizeof expect, "an integer in [%llu, %llu]", (unsigned long long)o->lo,
                         (unsigned long long)o->hi);
            else
                snprintf(expect, sizeof expect, "a non-negative integer");
            opts_fail(prog, "%s: expected %s, got '%s'", name, o->expect ? o->expect : expect, v);
        }
        *(uint64_t *)o->dst = (uint64_t)x;
        break;
    }
    case OPT_DOUBLE: {
        errno = 0;
        double x = strtod(v, &end);
        if (errno || end == v || *end || !isfinite(x) || x < o->lo || x > o->hi) {
            if (!o->expect) snprintf(expect, sizeof expect, "a number in [%g, %g]", o->lo, o->hi);
            opts_fail(prog, "%s: expected %s, got '%s'", name, o->expect ? o->expect : expect, v);
        }
        *(double *)o->dst = x;
        break;
    }
    case OPT_STRING:
        *(const char **)o->dst = v;
        break;
    case OPT_CHOICE: {
        int i = 0;
        while (o->choices[i] && strcmp(o->choices[i], v))
            i++;
        if (!o->choices[i]) {
            choice_list(o->choices, expect, sizeof expect);
            opts_fail(prog, "%s: expected %s, got '%s'", name, o->expect ? o->expect : expect, v);
        }
        if (o->dst) store_int(o, i);
        if (o->str) *o->str = o->choices[i];
        break;
    }
    case OPT_WXH: {
        long w = 0, h = 0;
        double lo2 = o->hi2 > 0 ? o->lo2 : o->lo, hi2 = o->hi2 > 0 ? o->hi2 : o->hi;
        bool ok = parse_long(v, &w, &end) && *end == 'x';
        ok = ok && parse_long(end + 1, &h, &end) && !*end;
        if (!ok || w < o->lo || w > o->hi || h < lo2 || h > hi2) {
            if (!o->expect) snprintf(expect, sizeof expect, "WxH with integers in %ld..%ld", (long)o->lo, (long)o->hi);
            opts_fail(prog, "%s: expected %s, got '%s'", name, o->expect ? o->expect : expect, v);
        }
        if (o->dst) ((int *)o->dst)[0] = (int)w, ((int *)o->dst)[1] = (int)h;
        if (o->str) *o->str = v;
        break;
    }
    case OPT_CALL: {
        char why[1024] = "bad value";
        if (!o->call(v, o->dst, why, sizeof why)) opts_fail(prog, "%s: %s", name, why);
        break;
    }
    default:
        ASSERT(!"an option that takes a value");
    }
}

/* The default an option gets when it is not given: at pass 0 those that do not depend on
 * --scale, at pass 1 those that do. */
static void set_default(const struct opts_spec *s, const struct opt *o, int pass)
{
    if (pass != (o->paper || o->full)) return;
    if (o->paper || o->full) {
        ASSERT(s->fig);
        const char *v = s->fig->scale_i == 1 && o->paper  ? o->paper
                        : s->fig->scale_i == 2 && o->full ? o->full
                                                          : o->def;
        if (v) set_value(s->prog, o, v);
        return;
    }
    const char *env = o->env ? getenv(o->env) : NULL;
    if (env && *env)
        set_value(s->prog, o, env);
    else if (o->def)
        set_value(s->prog, o, o->def);
    else if (o->def_int)
        store_int(o, o->def_int());
}

void opts_parse(const struct opts_spec *s, int argc, char **argv)
{
    int n = 0;
    while (s->opts[n].type != OPT_END)
        n++;
    bool *given = xcalloc((size_t)n + 1, sizeof *given);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            opts_help(s, stdout);
            exit(0);
        }
        if (a[0] != '-' || !a[1]) {
            if (!s->positional) opts_fail(s->prog, "unexpected argument '%s' (see --help)", a);
            s->positional(s->prog, a, s->ctx);
            continue;
        }
        const struct opt *o = opts_find(s, a);
        if (!o) opts_fail(s->prog, "unknown option '%s' (see --help)", a);
        given[o - s->opts] = true;
        if (o->type == OPT_FLAG) {
            store_int(o, o->value ? o->value : 1);
            continue;
        }
        if (i + 1 >= argc) opts_fail(s->prog, "%s needs a value (see --help)", a);
        set_value(s->prog, o, argv[++i]);
    }
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < n; k++)
            if (!given[k] && s->opts[k].name) set_default(s, &s->opts[k], pass);
        if (pass == 0 && s->fig) { /* --scale is known now; the defaults that depend on it follow */
            s->fig->prog = s->prog;
            s->fig->paper = s->fig->scale_i == 1;
            s->fig->full = s->fig->scale_i == 2;
            int scale_k = -1;
            bool has_full = false;
            for (int k = 0; k < n; k++) {
                has_full |= s->opts[k].full != NULL;
                if (s->opts[k].dst == &s->fig->scale_i) scale_k = k;
            }
            if (s->fig->full && !has_full && scale_k >= 0 && given[scale_k])
                opts_fail(s->prog, "--scale full: this figure has the scales quick and paper only");
            if (s->fig->full && !has_full) { /* SCALE=full (`make figures`): this figure's largest run short of paper */
                fprintf(stderr, "%s: SCALE=full: this figure has no full scale; running it at quick\n", s->prog);
                s->fig->scale_i = 0;
                s->fig->full = false;
                if (s->fig->scale) s->fig->scale = opts_scales[0];
            }
        }
    }
    free(given);
}

/* ---- --help ----------------------------------------------------------------------------------- */

enum { HELP_COL = 23, HELP_WIDTH = 100 };

/* `text` from column `col` (the cursor is there), wrapped at HELP_WIDTH with continuation lines
 * indented to HELP_COL. */
static void wrap(FILE *f, const char *text, int col)
{
    bool first = true;
    for (const char *p = text; *p;) {
        while (*p == ' ')
            p++;
        if (!*p) break;
        int w = (int)strcspn(p, " ");
        if (col + !first + w > HELP_WIDTH && col > HELP_COL) {
            fprintf(f, "\n%*s", HELP_COL, "");
            col = HELP_COL;
        } else if (!first) {
            fputc(' ', f);
            col++;
        }
        fprintf(f, "%.*s", w, p);
        col += w;
        p += w;
        first = false;
    }
    fputc('\n', f);
}

void opts_help(const struct opts_spec *s, FILE *f)
{
    fputs(s->usage, f);
    if (s->about) fputs(s->about, f);
    for (const struct opt *o = s->opts; o->type != OPT_END; o++) {
        if (o->type == OPT_TEXT) {
            fprintf(f, "%s\n", o->help);
            continue;
        }
        char left[256], arg[256], text[2048];
        if (o->type == OPT_CHOICE && !o->arg) {
            arg[0] = 0;
            for (int i = 0; o->choices[i]; i++)
                snprintf(arg + strlen(arg), sizeof arg - strlen(arg), "%s%s", i ? "|" : "", o->choices[i]);
        } else
            snprintf(arg, sizeof arg, "%s", o->arg ? o->arg : "");
        int col = snprintf(left, sizeof left, "  %s%s%s", o->name, *arg ? " " : "", arg);
        snprintf(text, sizeof text, "%s", o->help ? o->help : "");
        size_t l = strlen(text);
        if (o->full && o->def)
            snprintf(text + l, sizeof text - l, " (quick %s, paper %s, full %s)", o->def, o->paper ? o->paper : o->def,
                     o->full);
        else if (o->paper && o->def)
            snprintf(text + l, sizeof text - l, " (quick %s, paper %s)", o->def, o->paper);
        else if (o->paper)
            snprintf(text + l, sizeof text - l, " (paper %s)", o->paper);
        else if (o->env && o->def)
            snprintf(text + l, sizeof text - l, " (default $%s, else %s)", o->env, o->def);
        else if (o->def)
            snprintf(text + l, sizeof text - l, " (default %s)", o->def);
        fputs(left, f);
        if (col <= HELP_COL - 2) {
            fprintf(f, "%*s", HELP_COL - col, "");
            col = HELP_COL;
        } else {
            fputs("  ", f);
            col += 2;
        }
        wrap(f, text, col);
    }
    fprintf(f, "  --help, -h%*sthis text\n", HELP_COL - 12, "");
    if (s->tail) fputs(s->tail, f);
}

/* ---- shared groups ---------------------------------------------------------------------------- */

struct scene *opts_figure_scene(const struct opts_figure *f)
{
    char err[1024];
    struct scene *sc = scene_load(f->scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        exit(2);
    }
    outdir_require(f->prog, f->out);
    return sc;
}

struct scene *opts_accept_parse(struct opts_accept *a, const char *prog, const char *scene, const char *out,
                                const char *mutations_quick, const char *mutations_paper, int argc, char **argv)
{
    const struct opt opts[] = {OPTS_FIGURE(a->fig, scene, out),
                               OPT_MUTATIONS(a->mutations, .help = "mutations per method, over all lengths",
                                             .def = mutations_quick, .paper = mutations_paper),
                               OPT_MAX_LENGTH(a->max_length, .help = "longest path length", .def = "12"),
                               {0}};
    char usage[64];
    snprintf(usage, sizeof usage, "usage: %s [options]\n", prog);
    opts_parse(&(struct opts_spec){.prog = prog, .usage = usage, .opts = opts, .fig = &a->fig}, argc, argv);
    return opts_figure_scene(&a->fig);
}
