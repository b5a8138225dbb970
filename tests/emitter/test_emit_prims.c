/* Inversion round trips of the new emitters (thesis §5.1): the cap light's direction, the bilinear
 * environment's direction (its sampling weights changed), and the disk and cylinder emitters'
 * position and direction. Numbers u are drawn, sample(u) -> x, invert(x) -> u', and every
 * continuous u' is compared with u (discrete ones are fresh points of the chosen interval, so the
 * outcome is compared instead). Each case draws NRT = 200k and requires the failure fraction
 * (invert refused, or |u - u'| > RT_TOL) <= 1e-4; the maximum |u - u'| is logged. */
#include <criterion/criterion.h>

#include "emitter/emitter.h"
#include "emitter/emitter_table.h"
#include "scene/scene.h"
#include "support/emit_fixture.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <string.h>

#define NRT 200000
#define RT_TOL 1e-9
#define MAX_FAIL 1e-4

static struct sampler_writer W;
static double U[STREAM_COUNT][STREAM_DIMS];

/* Replays U from dimension 0 of the emitter stream. */
static void replay_u(struct sampler_replay *rp)
{
    sampler_replay_init(rp, (const double(*)[STREAM_DIMS])U);
    sampler_begin(&rp->base, STREAM_EMITTER, 0);
}

static void writer_begin(void)
{
    sampler_writer_clear(&W);
    sampler_begin(&W.base, STREAM_EMITTER, 0);
}

struct rt_stats {
    long n, fail;
    double max_err;
};

/* Compares dimensions [0, k) of the writer with U; discrete ones must only fall in the same cell,
 * which the caller checks by the outcome. */
static void rt_record(struct rt_stats *st, bool inverted, int k)
{
    st->n++;
    if (!inverted) {
        st->fail++;
        return;
    }
    double e = 0;
    for (int i = 0; i < k; i++)
        if (W.kind[STREAM_EMITTER][i] != DIM_DISCRETE) e = fmax(e, fabs(W.u[STREAM_EMITTER][i] - U[STREAM_EMITTER][i]));
    st->max_err = fmax(st->max_err, e);
    if (!(e <= RT_TOL)) st->fail++;
}

static void rt_report(const char *what, const struct rt_stats *st)
{
    double frac = (double)st->fail / (double)st->n;
    cr_log_info("%s: %ld samples, max |u - u'| %.3g, failure fraction %.3g", what, st->n, st->max_err, frac);
    fprintf(stderr, "roundtrip %-28s n %ld  max |u - u'| %.3g  failures %.3g\n", what, st->n, st->max_err, frac);
    cr_assert(frac <= MAX_FAIL, "%s: failure fraction %g (max error %g)", what, frac, st->max_err);
}

static void draw_u(rng *r, int k)
{
    for (int i = 0; i < k; i++)
        U[STREAM_EMITTER][i] = rng_uniform(r);
}

/* The fixture's environment turned into a cap light of the given half-angle about dir. */
static void cap_fixture(struct emit_fixture *f, vec3 dir, double deg)
{
    fx_init(f, FX_ENV_CONST, true);
    fx_free(f);
    struct prim *e = &f->prims[FX_ENV];
    e->env_is_cap = true;
    e->cap_dir = vnorm(dir);
    e->cap_cos = cos(deg * M_PI / 180);
    char err[256] = "";
    f->sc.emitters = emitters_build(&f->sc, err, sizeof err);
    cr_assert(f->sc.emitters, "%s", err);
}

static void cap_roundtrip(vec3 dir, double deg, const char *name)
{
    struct emit_fixture f;
    cap_fixture(&f, dir, deg);
    rng r;
    rng_seed(&r, 31, (uint64_t)deg);
    sampler_writer_init(&W, 32, (uint64_t)deg);
    struct rt_stats st = {0};
    for (long i = 0; i < NRT; i++) {
        draw_u(&r, 2);
        struct sampler_replay rp;
        replay_u(&rp);
        vec3 d;
        double pdf;
        cr_assert(env_sample_dir(&f.sc, &rp.base, &d, &pdf));
        cr_assert(fabs(pdf - env_pdf_dir(&f.sc, d)) <= 1e-12 * pdf);
        /* a direction on the cap's rim may round to just outside it: then radiance and pdf say 0 */
        if (!(env_pdf_dir(&f.sc, d) > 0)) {
            st.n++, st.fail++;
            continue;
        }
        cr_assert(vlen(vsub(env_radiance(&f.sc, d), f.prims[FX_ENV].emission)) == 0);
        writer_begin();
        rt_record(&st, env_invert_dir(&f.sc, d, &W.base), 2);
    }
    rt_report(name, &st);
    fx_free(&f);
}

/* Outside the cap: no radiance, no density, no inverse. */
static void cap_outside(vec3 dir, double deg)
{
    struct emit_fixture f;
    cap_fixture(&f, dir, deg);
    vec3 away = vneg(f.prims[FX_ENV].cap_dir);
    cr_assert(vzero(env_radiance(&f.sc, away)) && env_pdf_dir(&f.sc, away) == 0);
    writer_begin();
    cr_assert(!env_invert_dir(&f.sc, away, &W.base));
    fx_free(&f);
}

Test(emit_prims, cap_roundtrip_6deg) { cap_roundtrip(v3(0.3, 1, -0.4), 6, "cap 6 deg direction"); }
Test(emit_prims, cap_roundtrip_60deg) { cap_roundtrip(v3(-1, 0.2, 0.1), 60, "cap 60 deg direction"); }
Test(emit_prims, cap_outside_is_dark)
{
    cap_outside(v3(0.3, 1, -0.4), 6);
    cap_outside(v3(-1, 0.2, 0.1), 120);
}
Test(emit_prims, cap_roundtrip_whole_sphere) { cap_roundtrip(v3(0, 0, 1), 180, "cap 180 deg direction"); }

Test(emit_prims, env_bilinear_map_roundtrip)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_MAP, true);
    rng r;
    rng_seed(&r, 33, 0);
    sampler_writer_init(&W, 34, 0);
    struct rt_stats st = {0};
    for (long i = 0; i < NRT; i++) {
        draw_u(&r, 2);
        struct sampler_replay rp;
        replay_u(&rp);
        vec3 d;
        double pdf;
        cr_assert(env_sample_dir(&f.sc, &rp.base, &d, &pdf));
        cr_assert(fabs(pdf - env_pdf_dir(&f.sc, d)) <= 1e-9 * pdf, "%g vs %g", pdf, env_pdf_dir(&f.sc, d));
        writer_begin();
        rt_record(&st, env_invert_dir(&f.sc, d, &W.base), 2);
    }
    rt_report("env map (dilated weights)", &st);
    fx_free(&f);
}

/* ---- disk and cylinder emitters, loaded from JSON ---- */
static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "emit-prims"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static struct scene *load_emitter(const char *prim) { return fx_load_one_prim(tmpdir, prim); }
static void free_emitter(struct scene *s) { fx_free_loaded(s); }

/* Position (triangle pick + 2) then emitted direction (2), as an emitter vertex draws them. */
static void area_roundtrip(const char *prim, const char *name)
{
    struct scene *s = load_emitter(prim);
    rng r;
    rng_seed(&r, 35, strlen(name));
    sampler_writer_init(&W, 36, strlen(name));
    struct rt_stats st = {0};
    for (long i = 0; i < NRT; i++) {
        draw_u(&r, 5);
        struct sampler_replay rp;
        replay_u(&rp);
        struct emitter_pos pos;
        double pdf;
        cr_assert(emitter_sample_pos(s, 0, &rp.base, &pos));
        cr_assert(fabs(pos.pdf * s->prims[0].area - 1) < 1e-12);
        vec3 d = emitter_sample_dir(pos.n, &rp.base, &pdf);
        writer_begin();
        bool ok = emitter_invert_pos(s, 0, &pos, &W.base) && emitter_invert_dir(pos.n, d, &W.base);
        if (ok) { /* the discrete number must select the same triangle */
            struct sampler_replay rp2;
            sampler_replay_init(&rp2, (const double(*)[STREAM_DIMS])W.u);
            sampler_begin(&rp2.base, STREAM_EMITTER, 0);
            struct emitter_pos pos2;
            cr_assert(emitter_sample_pos(s, 0, &rp2.base, &pos2));
            ok = pos2.tri == pos.tri && vlen(vsub(pos2.p, pos.p)) <= 1e-9;
        }
        rt_record(&st, ok, 5);
    }
    rt_report(name, &st);
    free_emitter(s);
}

Test(emit_prims, disk_emitter_roundtrip, .init = mk_tmp, .fini = rm_tmp)
{
    area_roundtrip("{\"type\": \"disk\", \"bsdf\": \"w\", \"emission\": 3, \"transform\": {\"position\": [0.2, 1, "
                   "-0.3], \"scale\": 0.4, \"rotation\": [30, 10, 170]}}",
                   "disk position + direction");
}

Test(emit_prims, cylinder_emitter_roundtrip, .init = mk_tmp, .fini = rm_tmp)
{
    area_roundtrip("{\"type\": \"cylinder\", \"bsdf\": \"w\", \"power\": 10, \"transform\": {\"position\": [0, 1, 0], "
                   "\"scale\": [0.3, 1.5, 0.3], \"rotation\": [0, 30, 40]}}",
                   "cylinder position + direction");
}

/* power -> radiance on the tessellated shapes: P / (pi area), so the emitted flux is P. */
Test(emit_prims, cylinder_power_is_flux, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = load_emitter("{\"type\": \"cylinder\", \"bsdf\": \"w\", \"power\": 10}");
    double flux = M_PI * s->prims[0].area * s->prims[0].emission.x;
    cr_assert(fabs(flux - 10) < 1e-12, "flux %g", flux);
    free_emitter(s);
}
