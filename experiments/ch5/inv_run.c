/* One sampling function's density test (inv_run.h). */
#include "ch5/inv_run.h"
#include <math.h>
#include <string.h>

static uint64_t name_hash(const char *s)
{
    uint64_t h = 1469598103934665603ull; /* FNV-1a */
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211ull;
    return h;
}

void inv_run(const struct inv_func *f, struct inv_scratch *x, long n, uint64_t seed, double scale_first,
             struct inv_result *r)
{
    memset(r, 0, sizeof *r);
    uint64_t h = name_hash(f->name);
    struct inv_set ref, test;
    inv_set_init(&ref);
    inv_set_init(&test);
    double fwd[INV_SLOTS], inv[INV_SLOTS];
    long cap = 100 * n, i = 0;
    inv_rec_init(&x->rec, seed, h);
    for (long got = 0; got < n && i < cap; i++) {
        if (!inv_forward(f, x, i, fwd)) continue;
        inv_set_add(&ref, fwd);
        got++;
    }
    long ref_fails = i - ref.n;
    r->fwd_tries = i;
    inv_rec_init(&x->rec, seed, h ^ 0x5bd1e995u);
    sampler_writer_init(&x->w, seed, h ^ 0x27d4eb2fu);
    for (i = 0; r->samples + r->failures < n && i < cap; i++) {
        if (!inv_forward(f, x, i, fwd)) continue;
        if (!inv_inverse(f, x, inv)) {
            r->failures++;
            continue;
        }
        for (int k = 0; scale_first != 1 && k < INV_SLOTS; k++)
            if (!isnan(inv[k])) {
                inv[k] *= scale_first;
                break;
            }
        inv_set_add(&test, inv);
        r->samples++;
    }
    r->fwd_tries += i;
    r->fwd_fails = ref_fails + (i - r->samples - r->failures);
    r->uniform = r->fwd_fails == 0;
    inv_gof_evaluate(&test, r->uniform ? NULL : &ref, &r->g);
    inv_set_free(&ref);
    inv_set_free(&test);
}
