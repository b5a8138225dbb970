/* The MCMC option descriptors (mcmc/mlt_options.h): every number-changing option is in the
 * checkpoint identity, and every field of struct mlt_opts has a descriptor or a reason not to. */
#include <criterion/criterion.h>

#include "mcmc/mlt_options.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A value of the descriptor's type, within its bounds, other than the current one. */
static void change(const struct mlt_option *d, struct mlt_opts *o)
{
    double v = mlt_option_get(d, o), w;
    if (d->type == MLT_OPTION_FLAG)
        w = !v;
    else if (d->type == MLT_OPTION_CHOICE)
        w = d->choices[(int)v + 1] ? v + 1 : 0;
    else
        w = v != d->lo ? d->lo : d->hi;
    mlt_option_set(d, o, w);
    cr_assert_neq(mlt_option_get(d, o), v, "%s: no other value", d->key);
}

/* Iterates over the table: a descriptor added later is covered without a line here. */
Test(mlt_options, every_number_changing_option_changes_the_identity)
{
    struct mlt_opts base;
    mlt_opts_defaults(&base);
    base.method = MLT_MMLT;
    char id0[2048], id1[2048];
    mlt_options_identity(&base, id0, sizeof id0);
    int numbers = 0;
    for (size_t i = 0; i < mlt_options_count; i++) {
        const struct mlt_option *d = &mlt_options[i];
        struct mlt_opts o = base;
        change(d, &o);
        mlt_options_identity(&o, id1, sizeof id1);
        if (d->numbers)
            cr_expect_str_neq(id0, id1, "%s changes the numbers but not the identity", d->key);
        else
            cr_expect_str_eq(id0, id1, "%s does not change the numbers but changes the identity", d->key);
        numbers += d->numbers;
    }
    cr_assert_gt(numbers, 15);
}

/* The identity tells a small change of a real number apart (a %g would not). */
Test(mlt_options, identity_keeps_every_digit)
{
    struct mlt_opts a, b;
    mlt_opts_defaults(&a);
    b = a;
    b.pss.sigma = nextafter(a.pss.sigma, 1);
    char ia[2048], ib[2048];
    mlt_options_identity(&a, ia, sizeof ia);
    mlt_options_identity(&b, ib, sizeof ib);
    cr_assert_str_neq(ia, ib);
}

/* The member names of `struct NAME {` ... `};` in a header: the last identifier before each
 * top-level `;`, comments left out. */
static int struct_members(const char *path, const char *name, char out[][64], int max)
{
    FILE *f = fopen(path, "r");
    cr_assert(f, "%s: run from the repository's root", path);
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    char open[96];
    snprintf(open, sizeof open, "struct %s {", name);
    char *p = strstr(text, open);
    cr_assert(p, "no %s in %s", open, path);
    p += strlen(open);
    int count = 0, depth = 0;
    char last[64] = "";
    for (; *p && !(depth == 0 && *p == '}'); p++) {
        if (p[0] == '/' && p[1] == '*') {
            p = strstr(p + 2, "*/") + 1;
        } else if (*p == '{' || *p == '}') {
            depth += *p == '{' ? 1 : -1;
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            int l = 0;
            while ((isalnum((unsigned char)p[l]) || p[l] == '_') && l < 63)
                l++;
            memcpy(last, p, (size_t)l);
            last[l] = 0;
            p += l - 1;
        } else if ((*p == ';' || *p == ',') && depth == 0 && count < max) {
            strcpy(out[count++], last);
        }
    }
    return count;
}

/* Fields that are not options, and why. */
static const char *const not_options[] = {
    "method",              /* the method: bin/render's --method, the methods' registry */
    "pss",                 /* its fields below */
    "progress",            /* the progress bar: no effect on the numbers */
    "ckpt",                /* the checkpoint's control: where, not what */
    "pss.s1",    "pss.s2", /* Kelemen's step bounds: constants of the kernel (pss_opts_default) */
    "pss.width", "pss.height", "pss.rap_reference", /* the film's, from the scene and --resolution */
    NULL};

static bool covered(const char *field)
{
    for (const char *const *e = not_options; *e; e++)
        if (!strcmp(*e, field)) return true;
    for (size_t i = 0; i < mlt_options_count; i++)
        if (!strcmp(mlt_options[i].field, field)) return true;
    return false;
}

Test(mlt_options, every_field_has_a_descriptor)
{
    char members[64][64], field[96];
    int n = struct_members("core/mcmc/mlt.h", "mlt_opts", members, 64);
    cr_assert_gt(n, 20);
    for (int i = 0; i < n; i++)
        cr_expect(covered(members[i]), "struct mlt_opts.%s has no descriptor (mlt_options.c)", members[i]);
    n = struct_members("core/sampler/pss.h", "pss_opts", members, 64);
    cr_assert_gt(n, 8);
    for (int i = 0; i < n; i++) {
        snprintf(field, sizeof field, "pss.%s", members[i]);
        cr_expect(covered(field), "struct mlt_opts.%s has no descriptor (mlt_options.c)", field);
    }
}

/* The CSV groups' positions run without gaps, and every descriptor in a group is reached. */
Test(mlt_options, csv_groups_are_complete)
{
    const struct mlt_option *d[64];
    size_t in_groups = mlt_options_csv(MLT_CSV_BEFORE_COUNTS, d, 64) + mlt_options_csv(MLT_CSV_AFTER_COUNTS, d, 64);
    size_t declared = 0;
    for (size_t i = 0; i < mlt_options_count; i++)
        declared += mlt_options[i].csv_group != MLT_CSV_NONE;
    cr_assert_eq(in_groups, declared);
}
