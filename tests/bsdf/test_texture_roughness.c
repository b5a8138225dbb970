/* Textured roughness (README, "Textures"): the loader reads a roughness texture as Tungsten's
 * REQUEST_AVERAGE does (8-bit codes averaged in integers, not gamma-decoded; floats averaged),
 * bsdf_ctx_at looks it up at the hit's uv into c.roughness, and the rough BSDFs sample, evaluate
 * and invert with that value, so the inversion round trip holds at textured points. */
#include <criterion/criterion.h>

#include "bsdf/bsdf.h"
#include "bsdf/bsdf_json.h"
#include "io/oiio.h"
#include "sampler/sampler.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <string.h>

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "roughness-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static void write_image(const char *name, int w, int h, const float *px)
{
    char path[512], err[512] = "";
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    cr_assert(oiio_write(path, w, h, 3, px, err, sizeof err), "%s", err);
}

static struct scene *load_bsdfs(const char *bsdfs)
{
    char json[4096], path[512], err[1024] = "";
    snprintf(json, sizeof json,
             "{\"bsdfs\": [%s], \"primitives\": [{\"type\": \"quad\", \"bsdf\": \"a\"}],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 16,\n"
             "   \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             bsdfs);
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(json, 1, strlen(json), f), strlen(json));
    fclose(f);
    struct scene *s = scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s", err);
    bsdf_prepare_all(s->bsdfs, s->nbsdfs); /* needs_uv; scene_load does it for a rendered scene */
    return s;
}

/* A 2 x 1 PNG with texels of codes (10, 20, 31) and (200, 200, 200), and a 2 x 1 EXR. */
static void write_maps(void)
{
    const float png[6] = {10 / 255.f, 20 / 255.f, 31 / 255.f, 200 / 255.f, 200 / 255.f, 200 / 255.f};
    const float exr[6] = {0.1f, 0.2f, 0.6f, 0.5f, 0.5f, 0.5f};
    write_image("r.png", 2, 1, png);
    write_image("r.exr", 2, 1, exr);
}

Test(texture_roughness, read_as_tungstens_average_through_the_context, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct scene *s = load_bsdfs(
        "{\"name\": \"a\", \"type\": \"rough_conductor\", \"roughness\": \"r.png\"},"
        "{\"name\": \"b\", \"type\": \"rough_dielectric\", \"roughness\": {\"type\": \"bitmap\", \"file\": \"r.exr\"}},"
        "{\"name\": \"c\", \"type\": \"rough_plastic\", \"roughness\": {\"type\": \"checker\", \"on_color\": [0.3, "
        "0.9, 0.9],"
        " \"off_color\": 0.05, \"res_u\": 2, \"res_v\": 1}},"
        "{\"name\": \"d\", \"type\": \"rough_plastic\", \"roughness\": 0.25}");
    const struct bsdf *a = &s->bsdfs[0], *b = &s->bsdfs[1], *c = &s->bsdfs[2], *d = &s->bsdfs[3];
    cr_assert(a->roughness_tex && b->roughness_tex && c->roughness_tex && !d->roughness_tex);
    cr_assert(a->needs_uv && b->needs_uv && c->needs_uv && !d->needs_uv);
    double left[2] = {0.25, 0.5}, right[2] = {0.75, 0.5}, mid[2] = {0.5, 0.5};
    /* (10 + 20 + 31) / 3 = 20 in integers; 200 stays 200 (gamma-decoded it would be 149) */
    cr_assert_float_eq(bsdf_ctx_at(a, left).roughness, 20 / 255.0, 1e-7);
    cr_assert_float_eq(bsdf_ctx_at(a, right).roughness, 200 / 255.0, 1e-7);
    cr_assert_float_eq(bsdf_ctx_at(a, mid).roughness, 110 / 255.0, 1e-7); /* bilinear between them */
    cr_assert_float_eq(bsdf_ctx_at(b, left).roughness, 0.3, 1e-7);
    cr_assert_float_eq(bsdf_ctx_at(b, right).roughness, 0.5, 1e-7);
    /* a checker's first channel, as Tungsten reads .x() */
    cr_assert_eq(bsdf_ctx_at(c, left).roughness, 0.05);
    cr_assert_eq(bsdf_ctx_at(c, right).roughness, 0.3);
    cr_assert_eq(bsdf_ctx_at(d, right).roughness, 0.25);
    /* the albedo is untouched by the roughness map */
    cr_assert(bsdf_ctx_at(a, left).albedo.x == 1 && !a->albedo_tex);
    scene_model_free(s);
}

/* The rough BSDFs read c->roughness in sample, pdf, eval and invert: at a textured point each of
 * them gives exactly what the same BSDF with that roughness as a constant gives, and the inversion
 * round trip (sample, invert, replay: the same direction within 1e-6) holds there. 20000 samples per
 * BSDF and texel; at most 0.1 % of the round trips may fail, as in test_bsdf_rough.c. */
Test(texture_roughness, rough_bsdfs_sample_evaluate_and_invert_at_textured_points, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct scene *s = load_bsdfs("{\"name\": \"a\", \"type\": \"rough_conductor\", \"roughness\": \"r.png\"},"
                                 "{\"name\": \"b\", \"type\": \"rough_dielectric\", \"roughness\": \"r.png\"},"
                                 "{\"name\": \"c\", \"type\": \"rough_plastic\", \"distribution\": \"beckmann\","
                                 " \"roughness\": \"r.png\"}");
    rng r;
    rng_seed(&r, 7, 0);
    struct sampler_rng rs;
    sampler_rng_init(&rs, &r);
    static struct sampler_writer w;
    sampler_writer_init(&w, 9, 0);
    const double uvs[2][2] = {{0.25, 0.5}, {0.75, 0.5}};
    for (int k = 0; k < 3; k++) {
        const struct bsdf *tb = &s->bsdfs[k];
        for (int q = 0; q < 2; q++) {
            struct bsdf_ctx tc = bsdf_ctx_at(tb, uvs[q]);
            struct bsdf plain = *tb;
            plain.roughness_tex = NULL;
            plain.roughness = tc.roughness;
            struct bsdf_ctx pc = bsdf_ctx_at(&plain, NULL);
            long sampled = 0, good = 0;
            double worst = 0;
            for (int i = 0; i < 20000; i++) {
                double ct = 0.05 + 0.9 * rng_uniform(&r), ph = 2 * M_PI * rng_uniform(&r);
                vec3 wi = v3(sqrt(1 - ct * ct) * cos(ph), sqrt(1 - ct * ct) * sin(ph), ct);
                double u[SAMPLER_BLOCK];
                for (int j = 0; j < SAMPLER_BLOCK; j++)
                    u[j] = rng_uniform(&r);
                struct sampler_replay rp;
                double(*fixed)[STREAM_DIMS] = (double(*)[STREAM_DIMS])w.u;
                sampler_writer_clear(&w);
                memcpy(&fixed[STREAM_CAMERA][SAMPLER_BLOCK], u, sizeof u);
                struct bsdf_sample o1, o2;
                sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w.u);
                sampler_begin(&rp.base, STREAM_CAMERA, 1);
                bool ok1 = bsdf_sample(&tc, wi, &rp.base, TRANSPORT_RADIANCE, &o1);
                sampler_begin(&rp.base, STREAM_CAMERA, 1);
                bool ok2 = bsdf_sample(&pc, wi, &rp.base, TRANSPORT_RADIANCE, &o2);
                cr_assert_eq(ok1, ok2);
                if (!ok1) continue;
                cr_assert(vlen(vsub(o1.wo, o2.wo)) == 0 && o1.pdf == o2.pdf);
                cr_assert_eq(bsdf_pdf(&tc, wi, o1.wo), bsdf_pdf(&pc, wi, o1.wo));
                cr_assert(vlen(vsub(bsdf_eval(&tc, wi, o1.wo, TRANSPORT_RADIANCE),
                                    bsdf_eval(&pc, wi, o1.wo, TRANSPORT_RADIANCE))) == 0);
                sampled++;
                sampler_writer_clear(&w);
                sampler_begin(&w.base, STREAM_CAMERA, 1);
                if (!bsdf_invert(&tc, wi, o1.wo, &w.base)) continue;
                sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w.u);
                sampler_begin(&rp.base, STREAM_CAMERA, 1);
                if (!bsdf_sample(&tc, wi, &rp.base, TRANSPORT_RADIANCE, &o2)) continue;
                double e = vlen(vsub(o1.wo, o2.wo));
                worst = fmax(worst, e);
                if (e < 1e-6) good++;
            }
            cr_log_info("%s at u = %g (roughness %.4f): %ld of %ld round trips, worst %.3g", tb->name, uvs[q][0],
                        tc.roughness, good, sampled, worst);
            cr_assert(sampled > 5000, "%s: %ld samples", tb->name, sampled);
            cr_assert(good >= 0.999 * sampled, "%s at u = %g: %ld of %ld round trips (worst %g)", tb->name, uvs[q][0],
                      good, sampled, worst);
        }
    }
    scene_model_free(s);
}
