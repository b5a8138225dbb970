/* PITP's technique perturbation (thesis §5.2, core/mcmc/pitp.c): it leaves the path unchanged, its
 * partial inversion gives the numbers a full re-inversion gives, the technique keeps the path's
 * target, and the chosen technique follows the MIS weights w_j(x). Agreement of whole renders with
 * BDPT is in test_mlt.c and test_env.c beside the other MCMC methods. */
#include <criterion/criterion.h>

#include "mcmc/pitp.h"
#include "path/scene_ready.h"
#include "support/isa.h"
#include "support/scenes.h"
#include <gsl/gsl_cdf.h>
#include <stdio.h>
#include <string.h>

/* A chain state of length k: numbers from (seed, stream), evaluated as MMLT evaluates a state. */
struct tstate {
    struct pss_sampler pss;
    struct mmlt_path x;
    struct connection c;
};

static bool make_state(const struct path_ctx *pc, struct tstate *s, int k, uint64_t stream)
{
    struct pss_opts o;
    pss_opts_default(&o, pc->sc->cam.width, pc->sc->cam.height);
    pss_init(&s->pss, &o, 99, stream);
    bool ok = mmlt_eval(pc, &s->pss.base, k, &s->x, &s->c);
    pss_accept(&s->pss);
    return ok && luminance(s->c.f) * s->c.w > 0 && isfinite(luminance(s->c.f));
}

/* The path's vertices from the emitter end to the camera, whatever the technique. */
static int path_vertices(const struct mmlt_path *x, const struct vertex **out)
{
    int n = 0;
    for (int i = 0; i < x->s; i++)
        out[n++] = &x->emi[i];
    for (int i = x->t - 1; i >= 0; i--)
        out[n++] = &x->cam[i];
    return n;
}

static bool same_path(const struct mmlt_path *a, const struct mmlt_path *b, double tol)
{
    const struct vertex *va[2 * MAX_SUBPATH_VERTS], *vb[2 * MAX_SUBPATH_VERTS];
    int na = path_vertices(a, va), nb = path_vertices(b, vb);
    if (na != nb) return false;
    for (int i = 0; i < na; i++) {
        if (va[i]->prim != vb[i]->prim) return false;
        if (va[i]->kind == VK_ENV || vb[i]->kind == VK_ENV) {
            if (va[i]->kind != vb[i]->kind || vlen(vsub(va[i]->ng, vb[i]->ng)) > 1e-4) return false;
        } else if (vlen(vsub(va[i]->p, vb[i]->p)) > tol) {
            return false;
        }
    }
    return true;
}

static double rel_diff(double a, double b) { return fabs(a - b) / fmax(fabs(a), fabs(b)); }

/* The lobe that numbers u (all streams) make vertex blk of a subpath sample: where several lobes can
 * produce a direction, an inversion picks one at random (in proportion to its pdf share), and the
 * continuous numbers of two inversions are comparable only when they picked the same lobe. */
static int lobe_of(const double (*u)[STREAM_DIMS], int st, const struct vertex *v, int blk)
{
    struct sampler_replay rep;
    sampler_replay_init(&rep, u);
    sampler_begin(&rep.base, st, blk);
    struct bsdf_sample bs;
    enum transport mode = st == STREAM_CAMERA ? TRANSPORT_RADIANCE : TRANSPORT_IMPORTANCE;
    return bsdf_sample(&v[blk].bc, frame_to_local(&v[blk].sh, v[blk].wi), &rep.base, mode, &bs) ? bs.lobe : -1;
}

struct invariance {
    long perturbations, moved, failed, rejected, reevaluated, changed, target_off, weight_off, numbers_off, numbers,
        other_lobe;
};

/* Runs 4 consecutive perturbations from each of `nstates` states of lengths 2..7 on scene `path` and checks
 * after every move: the state's numbers replayed by MMLT's own evaluation give the same vertices
 * (within twice the retrace tolerance of the inverse-walk tests, 1e-4 of the scene's size), the same
 * target (relative 1e-2: vertices that agree within the tolerance still move a length-7 target at a
 * sharp glossy lobe by up to 0.7 %, seen on staircase and jewelry in a PGO=0 build; a wrong factor
 * in the re-evaluation is far larger), and a MIS weight of the new technique equal to the ratio the move was
 * sampled from (within 1e-6 + 1e-4 w: the retraced vertices differ in float; an independent evaluation of Eq. 5.21 in
 * the new technique's form); and a full re-inversion of the new path gives the same continuous numbers (1e-4) as the
 * partial one. One function per scene so that a loop over Embree ISAs can call it. */
static void pitp_invariance_on_scene(const char *path, int nstates, struct invariance *r)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct tstate s;
    static struct mmlt_path before, replay;
    static struct pitp_scratch ws;
    static struct nonfinite nf;
    static struct sampler_writer wr;
    pitp_scratch_init(&ws, sc);
    sampler_writer_init(&wr, 3, 0);
    rng r0;
    rng_seed(&r0, 17, 0);
    *r = (struct invariance){0};
    /* states with a contribution: nstates of them, or as many as 2M tries find (ajar's are rare) */
    int states = 0;
    for (int i = 0; i < 2000000 && states < nstates; i++) {
        int k = 2 + i % 6;
        if (!make_state(&pc, &s, k, (uint64_t)i)) continue;
        states++;
        for (int rep = 0; rep < 4; rep++) {
            before = s.x;
            double target = luminance(s.c.f) * s.c.w, sum = 0;
            for (int j = 0; j <= k; j++)
                sum += s.x.ratios[j];
            int j;
            double a;
            struct connection cn;
            bool c_new;
            enum pitp_outcome po = pitp_perturb(&pc, &s.pss, &s.x, &ws, rng_uniform(&r0), &j, &a, &cn, &c_new, &nf);
            r->perturbations++;
            if (po == PITP_FAILED) r->failed++;
            if (po == PITP_REJECTED) r->rejected++;
            if (po != PITP_MOVED) continue;
            r->moved++;
            struct connection c;
            bool ok = mmlt_eval(&pc, &s.pss.base, k, &replay, &c);
            /* 2 tol: the move kept the path within tol of its retrace, and this replay from the
             * numbers is a third trace, within tol of that one (a k = 7 living-room path through two
             * delta vertices came out 1.04 tol off in a PGO=0 build, 0.9 tol in the default one) */
            if (!ok || replay.t != s.x.t || !same_path(&before, &replay, 2 * ws.tol)) {
                r->changed++;
                continue;
            }
            if (c_new) {
                r->reevaluated++;
                if (rel_diff(luminance(c.f) * c.w, luminance(cn.f) * cn.w) > 1e-2) r->target_off++;
            } else if (rel_diff(luminance(c.f) * c.w, target) > 1e-2) {
                r->target_off++;
            }
            if (fabs(c.w - before.ratios[j] / sum) > 1e-6 + 1e-4 * c.w) r->weight_off++;
            sampler_writer_clear(&wr);
            if (!invert_camera(&pc, replay.cam, replay.t, 0, &wr.base) ||
                !invert_emitter(&pc, replay.emi, replay.s, 0, &wr.base))
                continue;
            static double cur[STREAM_COUNT][STREAM_DIMS];
            for (int st = 0; st < STREAM_COUNT; st++)
                for (int d = 0; d < STREAM_DIMS; d++)
                    cur[st][d] = s.pss.d[st][d].value;
            for (int st = 0; st < 2; st++)
                for (int d = 0; d < STREAM_DIMS; d++) {
                    /* deterministic numbers only: not discrete choices, nor the numbers a delta lobe
                     * ignores (both inversions fill those with fresh uniforms), nor those of a scattering
                     * block whose two inversions picked different lobes */
                    const struct vertex *v = st == STREAM_CAMERA ? replay.cam : replay.emi;
                    int blk = d / SAMPLER_BLOCK, nv = st == STREAM_CAMERA ? replay.t : replay.s;
                    if (isnan(wr.u[st][d]) || wr.kind[st][d] == DIM_DISCRETE || (blk > 0 && v[blk].delta)) continue;
                    if (blk > 0 && blk + 1 < nv && v[blk].bc.b &&
                        lobe_of((const double(*)[STREAM_DIMS])wr.u, st, v, blk) !=
                            lobe_of((const double(*)[STREAM_DIMS])cur, st, v, blk)) {
                        r->other_lobe++;
                        continue;
                    }
                    r->numbers++;
                    if (fabs(wr.u[st][d] - s.pss.d[st][d].value) > 1e-4) r->numbers_off++;
                }
            s.c = c;
        }
    }
    fprintf(stderr,
            "pitp invariance %s: %ld perturbations, %ld moved (%ld re-evaluated), %ld rejected by f_j/f_i, "
            "%ld failed (%.4f %%), %ld changed the path, %ld target, %ld weight, %ld of %ld numbers off (%ld in blocks "
            "inverted to another lobe, not compared)\n",
            path, r->perturbations, r->moved, r->reevaluated, r->rejected, r->failed,
            100.0 * r->failed / r->perturbations, r->changed, r->target_off, r->weight_off, r->numbers_off, r->numbers,
            r->other_lobe);
    cr_assert(r->moved > r->perturbations / 20, "%s: only %ld of %ld perturbations moved", path, r->moved,
              r->perturbations);
    cr_assert(r->changed <= r->moved / 1000, "%s: %ld of %ld moves changed the path", path, r->changed, r->moved);
    cr_assert(r->target_off <= r->moved / 1000, "%s: %ld of %ld moves changed the target", path, r->target_off,
              r->moved);
    cr_assert(r->weight_off <= r->moved / 1000, "%s: %ld of %ld moves: MIS weight of j is not ratio_j / sum", path,
              r->weight_off, r->moved);
    cr_assert(r->numbers_off <= r->numbers / 1000, "%s: partial vs full inversion: %ld of %ld numbers differ", path,
              r->numbers_off, r->numbers);
    scene_free(sc);
}

static void invariance_under_isa(const char *isa, void *ctx)
{
    (void)ctx;
    fprintf(stderr, "pitp invariance under Embree ISA %s\n", isa);
    const char **s = test_all_scenes();
    cr_assert(s[0], "no scenes found under scenes/");
    struct invariance r;
    /* 6000 perturbations per scene and ISA: the 0.1 % bound still allows only 6 changed paths */
    for (; *s; s++)
        pitp_invariance_on_scene(*s, 1500, &r);
}

/* Hit points differ in their last bits between Embree's kernels (tests/isa.h): the path must stay
 * unchanged under every kernel this machine runs, not only under its best. */
Test(pitp, perturbation_leaves_the_path_unchanged_on_every_scene, .timeout = 600)
{
    test_each_isa(invariance_under_isa, NULL);
}

/* The same on the texture conformance scenes (default Embree kernel): bump maps and textured
 * roughness make the shading frame and the BSDF functions of the hit point, which the
 * perturbation's inversions must see unchanged. */
Test(pitp, perturbation_leaves_the_path_unchanged_on_textured_scenes, .timeout = 600)
{
    const char *scenes[] = {"tests/data/tungsten/bump-map.json", "tests/data/tungsten/texture-roughness.json",
                            "tests/data/tungsten/texture-checker.json"};
    struct invariance r;
    for (int i = 0; i < 3; i++)
        pitp_invariance_on_scene(scenes[i], 1500, &r);
}

/* The chosen technique follows w_j(x) = (p_j / p_i) / sum_l (p_l / p_i) (Eq. 5.22-5.25): for each
 * perturbation, a randomised probability integral transform of j under w (a uniform point of j's
 * interval of w's CDF) is U(0, 1) whatever the state. 50000 perturbations per scene (4 in a row
 * from each of 12500 states with a contribution, lengths 1..6; Cornell box and materials), 20 equal bins, chi-square
 * with 19 degrees of freedom, alpha = 0.01 Sidak over the 2 scenes. */
Test(stat_pitp, technique_choice_follows_mis_weights)
{
    const char *scenes[] = {"scenes/cornell-box/scene.json", "scenes/materials/scene.json"};
    double alpha = 1 - pow(0.99, 1.0 / 2);
    for (int sci = 0; sci < 2; sci++) {
        struct scene *sc = test_scene(scenes[sci]);
        struct path_ctx pc = {.sc = sc, .max_length = 8};
        static struct tstate s;
        static struct pitp_scratch ws;
        static struct nonfinite nf;
        pitp_scratch_init(&ws, sc);
        rng r0, r1;
        rng_seed(&r0, 23, 0);
        rng_seed(&r1, 29, 0);
        double bins[20] = {0};
        long n = 0;
        int states = 0;
        for (int i = 0; i < 2000000 && states < 12500; i++) {
            int k = 1 + i % 6;
            if (!make_state(&pc, &s, k, 100000 + (uint64_t)i)) continue;
            states++;
            for (int rep = 0; rep < 4; rep++) {
                double sum = 0, lo = 0;
                for (int j = 0; j <= k; j++)
                    sum += s.x.ratios[j];
                double w[MAX_PATH_LENGTH + 2];
                for (int j = 0; j <= k; j++)
                    w[j] = s.x.ratios[j] / sum;
                int j;
                double a;
                struct connection cn;
                bool c_new;
                pitp_perturb(&pc, &s.pss, &s.x, &ws, rng_uniform(&r0), &j, &a, &cn, &c_new, &nf);
                if (c_new) s.c = cn;
                for (int l = 0; l < j; l++)
                    lo += w[l];
                double v = lo + rng_uniform(&r1) * w[j];
                int b = (int)(20 * v);
                bins[b < 0 ? 0 : b > 19 ? 19 : b]++;
                n++;
            }
        }
        double chi = 0;
        for (int b = 0; b < 20; b++)
            chi += sqr(bins[b] - n / 20.0) / (n / 20.0);
        double p = gsl_cdf_chisq_Q(chi, 19);
        fprintf(stderr, "pitp technique choice %s: chi2 = %.2f (19 dof), p = %.4f over %ld draws\n", scenes[sci], chi,
                p, n);
        cr_assert(n == 50000, "%s: only %ld perturbations", scenes[sci], n);
        cr_assert(p > alpha, "%s: chosen techniques do not follow w_j: chi2 = %.1f, p = %g (%ld draws)", scenes[sci],
                  chi, p, n);
        scene_free(sc);
    }
}

/* Counts of technique transitions (from i, to j) per length, from `states` states of scene sc, each
 * brought to w(x) by two perturbations (one move that is not refused draws j from w exactly) and
 * then counted over a third. Paths whose target can change with the technique are skipped: their
 * stationary law is not w. one_way: every move toward more emitter vertices is undone, a chain
 * whose moves i -> j are allowed while j -> i are refused. */
struct flows {
    long n[MAX_PATH_LENGTH + 1][MAX_PATH_LENGTH + 2][MAX_PATH_LENGTH + 2];
};

static void count_flows(const struct scene *sc, int states, bool one_way, struct flows *fl)
{
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct tstate s, keep;
    static struct pitp_scratch ws;
    static struct nonfinite nf;
    pitp_scratch_init(&ws, sc);
    rng r0;
    rng_seed(&r0, 31, one_way);
    memset(fl, 0, sizeof *fl);
    int found = 0;
    for (int i = 0; i < 4000000 && found < states; i++) {
        int k = 2 + i % 5;
        if (!make_state(&pc, &s, k, 300000 + (uint64_t)i) || pitp_target_may_change(&s.x)) continue;
        found++;
        for (int rep = 0; rep < 3; rep++) {
            int from = s.x.s, j;
            double a;
            struct connection cn;
            bool c_new;
            if (one_way) keep = s;
            enum pitp_outcome po = pitp_perturb(&pc, &s.pss, &s.x, &ws, rng_uniform(&r0), &j, &a, &cn, &c_new, &nf);
            if (one_way && po == PITP_MOVED && j > from) s = keep;
            if (rep == 2) fl->n[k][from][s.x.s]++;
        }
    }
    cr_assert(found == states, "%s: only %d states", sc->file, found);
}

/* Smallest two-sided binomial p of n_ij against half of n_ij + n_ji over the pairs with at least 20
 * transitions; *tests receives their number. */
static double worst_flow_p(const struct flows *fl, int *tests)
{
    double worst = 1;
    *tests = 0;
    for (int k = 2; k <= 6; k++)
        for (int i = 0; i <= k; i++)
            for (int j = i + 1; j <= k; j++) {
                long a = fl->n[k][i][j], n = a + fl->n[k][j][i];
                if (n < 20) continue;
                (*tests)++;
                double lo = gsl_cdf_binomial_P((unsigned)a, 0.5, (unsigned)n),
                       hi = a ? gsl_cdf_binomial_Q((unsigned)a - 1, 0.5, (unsigned)n) : 1;
                worst = fmin(worst, fmin(1.0, 2 * fmin(lo, hi)));
            }
    return worst;
}

/* Detailed balance of the technique perturbation at a fixed path (core/mcmc/README.md, "Failed
 * inversions keep detailed balance"): with the technique distributed as w(x), the flow i -> j
 * equals the flow j -> i whenever moves are allowed or refused in pairs. 40000 states per scene
 * (lengths 2..6; Cornell box, and scenes/materials' glossy and diffuse paths), one counted
 * transition each; two-sided binomial test per length and pair (i, j) with >= 20 transitions,
 * alpha = 0.01 Sidak over all pairs of both scenes. Consecutive transitions of one state are not
 * counted, so the counts are independent. The same count from a chain that undoes every move toward
 * more emitter vertices must fail it: the test cannot pass on a one-way chain. */
Test(stat_pitp, moves_between_two_techniques_balance_and_a_one_way_chain_fails, .timeout = 300)
{
    const char *scenes[] = {"scenes/cornell-box/scene.json", "scenes/materials/scene.json"};
    static struct flows fl;
    double worst[2][2];
    int tests[2][2], total = 0;
    for (int sci = 0; sci < 2; sci++) {
        struct scene *sc = test_scene(scenes[sci]);
        for (int broken = 0; broken < 2; broken++) {
            count_flows(sc, 40000, broken, &fl);
            worst[sci][broken] = worst_flow_p(&fl, &tests[sci][broken]);
        }
        total += tests[sci][0];
        scene_free(sc);
    }
    double alpha = 1 - pow(0.99, 1.0 / total);
    for (int sci = 0; sci < 2; sci++) {
        fprintf(stderr,
                "pitp flow balance %s: worst pair p = %.3g over %d pairs (alpha %.2g); one-way chain: %.3g over %d\n",
                scenes[sci], worst[sci][0], tests[sci][0], alpha, worst[sci][1], tests[sci][1]);
        cr_assert(tests[sci][0] >= 10, "%s: only %d pairs with enough transitions", scenes[sci], tests[sci][0]);
        cr_assert(worst[sci][0] > alpha, "%s: flows i -> j and j -> i differ: p = %g (alpha %g)", scenes[sci],
                  worst[sci][0], alpha);
        cr_assert(worst[sci][1] <= alpha, "%s: a one-way chain passed the balance test (p = %g)", scenes[sci],
                  worst[sci][1]);
    }
}
