/* The MCMC options on bin/render's command line and in its CSV, from their descriptors. */
#include "tools/mlt_cli.h"
#include "common/csv_meta.h"
#include <string.h>

static const enum opt_type opt_types[] = {[MLT_OPTION_FLAG] = OPT_FLAG,
                                          [MLT_OPTION_INT] = OPT_INT,
                                          [MLT_OPTION_DOUBLE] = OPT_DOUBLE,
                                          [MLT_OPTION_CHOICE] = OPT_CHOICE};

size_t mlt_cli_opts(struct mlt_opts *m, struct opt *out, size_t max)
{
    size_t n = 0;
    for (size_t i = 0; i < mlt_options_count && n < max; i++) {
        const struct mlt_option *d = &mlt_options[i];
        if (!d->cli) continue;
        out[n++] = (struct opt){.name = d->cli,
                                .type = opt_types[d->type],
                                .dst = (char *)m + d->offset,
                                .size = d->size,
                                .arg = d->arg,
                                .help = d->help,
                                .def = d->def,
                                .lo = d->lo,
                                .hi = d->hi,
                                .choices = d->choices,
                                .tag = (int)d->methods};
    }
    return n;
}

/* "a", "a and b", "a, b and c": the methods of a mask. */
static void method_list(unsigned mask, char *buf, size_t n)
{
    int count = 0, seen = 0;
    for (int i = 0; mlt_option_methods[i]; i++)
        count += (mask >> i) & 1;
    buf[0] = 0;
    for (int i = 0; mlt_option_methods[i]; i++) {
        if (!((mask >> i) & 1)) continue;
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "%s%s", seen == 0 ? "" : seen == count - 1 ? " and " : ", ", mlt_option_methods[i]);
        seen++;
    }
}

void mlt_cli_warn_unused(const struct opts_spec *spec, const char *method, int argc, char **argv)
{
    unsigned bit = mlt_method_bit(method);
    char only[128];
    for (int i = 1; i < argc; i++) {
        const struct opt *e = opts_find(spec, argv[i]);
        if (!e || !e->tag || (e->tag & bit)) continue;
        method_list((unsigned)e->tag, only, sizeof only);
        fprintf(stderr, "render: warning: %s has no effect with --method %s (it applies to %s)\n", argv[i], method,
                only);
    }
}

void mlt_cli_csv(FILE *f, const struct mlt_opts *m, enum mlt_csv_group g)
{
    const struct mlt_option *d[64];
    size_t n = mlt_options_csv(g, d, sizeof d / sizeof d[0]);
    char v[64];
    for (size_t i = 0; i < n; i++) {
        if (d[i]->csv_own && !(d[i]->methods & mlt_method_mask(m->method))) continue;
        if (d[i]->csv_if && !d[i]->csv_if(m)) continue;
        mlt_option_format(d[i], m, true, v, sizeof v);
        csv_meta(f, d[i]->csv_key, "%s", v);
    }
}
