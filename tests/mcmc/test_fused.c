/* The fused perturbations' map back to primary sample space (core/mcmc/fused.c): a path that
 * Veach's lens or caustic perturbation makes of an MMLT state is inverted by the state's technique,
 * and the walks of those numbers retrace it (perturb, invert, resample). The state's own path
 * inverts and retraces too, so a proposal refused for its inversion is one whose reverse move
 * could never be made (docs/fused.md). Agreement of whole renders with BDPT is in test_mlt.c. */
#include <criterion/criterion.h>

#include "mcmc/fused.h"
#include "mcmc/mlt_options.h"
#include "path/path_form.h"
#include "path/scene_ready.h"
#include "support/isa.h"
#include "support/scenes.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const names[] = {"lens", "caustic", "multi-chain"};

struct counts {
    long states, own_ok;
    long made[3], inverted[3], retraced[3]; /* [0] lens, [1] caustic, [2] multi-chain */
};

/* yp (moved from x'_lo on; 0: inverted whole) inverted over the state's numbers (pss) and replayed.
 * 0: the inversion failed; 1: inverted, the walks went elsewhere; 2: inverted and retraced. */
static int invert_and_replay(const struct path_ctx *pc, const struct mmlt_path *x, const struct pss_sampler *pss,
                             const struct vertex *const *yp, int lo, struct veach_scratch *w, struct sampler_writer *wr,
                             struct mmlt_path *y, double tol)
{
    pss_export(pss, wr->u); /* the numbers the inversion keeps, the technique number among them */
    if (!fused_invert(pc, x, yp, lo, w, &wr->base)) return 0;
    struct sampler_replay rp; /* aborts on a number neither the state nor the inversion has */
    sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])wr->u);
    struct connection c;
    mmlt_eval(pc, &rp.base, x->k, y, &c);
    return y->complete && y->t == x->t && fused_retraced(y, lo, w, tol) ? 2 : 1;
}

/* MMLT states with a contribution, lengths 2..7 from fresh numbers, until `want` of them; each
 * perturbation counted as made when the perturbed path has a contribution (one without, whose
 * technique may not reach it, is never a state and never accepted). */
static void resample_on_scene(const char *path, long want, struct counts *r)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct pss_sampler pss;
    static struct mmlt_path x, y;
    static struct veach_scratch w;
    static struct sampler_writer wr;
    struct pss_opts o;
    pss_opts_default(&o, sc->cam.width, sc->cam.height);
    sampler_writer_init(&wr, 5, 0);
    double tol = 1e-4 * fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min)));
    rng rg;
    rng_seed(&rg, 31, 0);
    *r = (struct counts){0};
    for (long i = 0; i < 4000000 && r->states < want; i++) {
        int k = 2 + (int)(i % 6);
        pss_init(&pss, &o, 77, (uint64_t)i);
        struct connection c;
        if (!mmlt_eval(&pc, &pss.base, k, &x, &c) || !(luminance(c.f) * c.w > 0)) continue;
        r->states++;
        fused_state_of(&w.xm, &x, c.px, c.py);
        const struct vertex *yp[MAX_SUBPATH_VERTS];
        for (int j = 0; j <= k; j++)
            yp[j] = &w.xm.x[j]; /* the state's own path, unperturbed */
        r->own_ok += invert_and_replay(&pc, &x, &pss, yp, 0, &w, &wr, &y, tol) == 2;
        for (int p = 0; p < 3; p++) {
            int m = p == 0   ? veach_lens_vertex(&w.xm)
                    : p == 1 ? veach_caustic_vertex(&w.xm)
                             : veach_multichain_vertex(&w.xm);
            double p_old, p_new;
            if (m < 0 || !(p == 0   ? veach_lens_perturb(&pc, &rg, &w.xm, m, &w, yp)
                           : p == 1 ? veach_caustic_perturb(&pc, &rg, &w.xm, m, &w, &p_old, &p_new, yp)
                                    : veach_multichain_perturb(&pc, &rg, &w.xm, m, &w, &p_new, yp)))
                continue;
            /* connected at the split the perturbation's acceptance uses, as Veach's steps do */
            bool lit =
                p == 1 ? path_camera_form(&pc, yp, k, 1, w.zs) && veach_state_set(&w.y, &pc, w.ys, k, w.zs, 1)
                       : path_emitter_form(&pc, yp, m, w.ys) && veach_state_set(&w.y, &pc, w.ys, m, w.zs, k + 1 - m);
            if (!lit) continue;
            r->made[p]++;
            int res = invert_and_replay(&pc, &x, &pss, yp, p == 1 ? m + 1 : m, &w, &wr, &y, tol);
            r->inverted[p] += res > 0;
            r->retraced[p] += res == 2;
        }
    }
    fprintf(stderr, "%s: %ld states, own path retraced %ld", path, r->states, r->own_ok);
    for (int p = 0; p < 3; p++)
        fprintf(stderr, "; %s made %ld inverted %ld retraced %ld", names[p], r->made[p], r->inverted[p],
                r->retraced[p]);
    fputc('\n', stderr);
    scene_free(sc);
}

/* Every committed scene under each of Embree's instruction sets (hit points differ in their last
 * bits between its kernels): 2000 states each. The state's own path inverts and retraces in at least
 * 99.9 % of states, and a perturbed one in at least 99 % of those made, the lens perturbation at
 * least 50 times (window's camera sees most light through its pane: 77); the caustic one at least 20 times where
 * caustics lie on diffuse surfaces the camera sees (materials, glass-marble); the multi-chain one
 * wherever it is made (the scenes with specular chains between diffuse vertices). */
static void check_all(const char *isa, void *ctx)
{
    (void)ctx;
    for (const char **sp = test_all_scenes(); *sp; sp++) {
        struct counts r;
        resample_on_scene(*sp, 2000, &r);
        cr_assert_geq(r.states, 2000, "%s (%s): states", *sp, isa);
        cr_assert_geq(r.own_ok, 0.999 * r.states, "%s (%s): own path retraced %ld of %ld", *sp, isa, r.own_ok,
                      r.states);
        for (int p = 0; p < 3; p++)
            cr_assert_geq(r.retraced[p], 0.99 * r.made[p], "%s (%s): %s: %ld of %ld retraced", *sp, isa, names[p],
                          r.retraced[p], r.made[p]);
        cr_assert_geq(r.made[0], 50, "%s (%s): lens perturbations made: %ld", *sp, isa, r.made[0]);
        if (strstr(*sp, "/materials/") || strstr(*sp, "/glass-marble/"))
            cr_assert_geq(r.made[1], 20, "%s (%s): caustic perturbations made: %ld", *sp, isa, r.made[1]);
    }
}

Test(fused, perturbed_paths_invert_and_retrace_on_every_scene, .timeout = 900)
{
    cr_assert(test_all_scenes()[0], "no scenes found under scenes/");
    test_each_isa(check_all, NULL);
}

/* A render's own count of the same (mlt_stats.fused_inverted and fused_not_inverted, the CSV's
 * fused_inverted and fused_inversion_failures): MMLT on the Cornell box (32x32, 64 mutations per
 * pixel, every small step a fused lens perturbation) inverts more than a thousand perturbed paths
 * and at least 95 % of them retrace: above, 99 % of those with a contribution do; a run also
 * inverts paths without one (the chain rejects them whatever the inversion says), whose walks may
 * not reach them. The failures are a part of the rows' `failed`, which also counts the refusals
 * before inversion (most of it here). */
Test(fused, a_render_counts_its_inversions, .timeout = 120)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    struct mlt_opts o;
    mlt_opts_defaults(&o);
    pss_opts_default(&o.pss, 32, 32);
    o.method = MLT_MMLT;
    o.mutations = 32L * 32 * 64;
    o.seed_paths = 5000;
    o.threads = 2;
    o.max_length = 8;
    o.fused = FUSED_LENS;
    o.fused_rate = 1;
    struct mlt_result r;
    char err[256];
    cr_assert(mlt_render(sc, &o, &r, err, sizeof err), "%s", err);
    const struct accept_cell *lens = &r.stats.total[PROPOSAL_FUSED_LENS];
    fprintf(stderr, "fused lens on the Cornell box: %ld proposals, %ld failed, %ld inverted, %ld not\n", lens->attempts,
            lens->failed, r.stats.fused_inverted, r.stats.fused_not_inverted);
    cr_assert_gt(r.stats.fused_inverted, 1000);
    cr_assert_leq(r.stats.fused_inverted, lens->attempts);
    cr_assert_leq(r.stats.fused_not_inverted, lens->failed);
    cr_assert_leq(r.stats.fused_not_inverted, 0.05 * r.stats.fused_inverted);
    mlt_result_free(&r);
    scene_free(sc);
}
