/* Thin-lens camera (camera.h): sampling against its projection and its inverse, the inverse camera
 * walk (lens point and image position), the loader's fields and refusals. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "camera/camera.h"
#include "path/path.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

#define SCENE "tests/data/tungsten/camera-thinlens.json"

/* Circular distance: the disc's angle number wraps at 1. */
static double dist_wrap(double a, double b)
{
    double d = fabs(a - b);
    return fmin(d, 1 - d);
}

/* N = 200k lens points and image positions from fresh numbers, box and tent film: the projection
 * camera_raster of the sampled ray from the sampled lens point gives back the raster point and the
 * density, and camera_invert_lens + camera_invert give back the four numbers. Measured: raster
 * error < 1e-11 px, number error < 1e-12 (asserted: 1e-8 px, 1e-9). */
static void roundtrip(enum recon_filter f)
{
    struct scene *sc = test_scene(SCENE);
    struct camera c = sc->cam;
    c.filter = f;
    cr_assert(c.lens_radius == 0.12 && c.focus_dist == 2.2);
    struct sampler_writer W, U;
    sampler_writer_init(&W, 3, 0);
    sampler_writer_init(&U, 4, 0);
    rng r;
    rng_seed(&r, 21, 0);
    const int N = 200000;
    double max_raster = 0, max_u = 0, max_p = 0;
    for (int i = 0; i < N; i++) {
        for (int k = 0; k < 4; k++)
            U.u[STREAM_CAMERA][k] = rng_uniform(&r);
        struct sampler_replay rp;
        sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])U.u);
        sampler_begin(&rp.base, STREAM_CAMERA, 0);
        double pdf_lens, px, py, pdf, qx, qy;
        vec3 lens = camera_sample_lens(&c, &rp.base, &pdf_lens);
        vec3 d = camera_sample_dir(&c, lens, &rp.base, &px, &py, &pdf);
        cr_assert_eq(rp.base.offset, 4);
        cr_assert(fabs(pdf_lens * M_PI * 0.12 * 0.12 - 1) < 1e-12);
        double pr = camera_raster(&c, lens, d, &qx, &qy);
        cr_assert(pr > 0 && fabs(pr / pdf - 1) < 1e-9, "sampled pdf %g, raster pdf %g", pdf, pr);
        max_raster = fmax(max_raster, fmax(fabs(qx - px), fabs(qy - py)));
        sampler_writer_clear(&W);
        sampler_begin(&W.base, STREAM_CAMERA, 0);
        cr_assert(camera_invert_lens(&c, lens, &W.base));
        camera_invert(&c, qx, qy, &W.base);
        cr_assert_eq(W.kind[STREAM_CAMERA][0], DIM_CONTINUOUS);
        cr_assert_eq(W.kind[STREAM_CAMERA][2], DIM_IMAGE_X);
        cr_assert_eq(W.kind[STREAM_CAMERA][3], DIM_IMAGE_Y);
        for (int k = 0; k < 4; k++) {
            double e = k == 1 ? dist_wrap(W.u[STREAM_CAMERA][k], U.u[STREAM_CAMERA][k])
                              : fabs(W.u[STREAM_CAMERA][k] - U.u[STREAM_CAMERA][k]);
            max_u = fmax(max_u, e);
        }
        sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])W.u);
        sampler_begin(&rp.base, STREAM_CAMERA, 0);
        max_p = fmax(max_p, vlen(vsub(camera_sample_lens(&c, &rp.base, &pdf_lens), lens)));
    }
    fprintf(stderr, "thinlens %s: N %d, max raster error %.3g px, max |u - invert(sample(u))| %.3g, lens point %.3g\n",
            f == FILTER_BOX ? "box" : "tent", N, max_raster, max_u, max_p);
    cr_assert(max_raster < 1e-8, "%g", max_raster);
    cr_assert(max_u < 1e-9, "%g", max_u);
    scene_free(sc);
}
Test(thinlens, sample_raster_invert_roundtrip_box) { roundtrip(FILTER_BOX); }
Test(thinlens, sample_raster_invert_roundtrip_tent) { roundtrip(FILTER_TENT); }

/* The focus plane: every lens point sees a point of the plane in focus at the same raster
 * position, and rays through the lens centre are the pinhole's. */
Test(thinlens, focus_plane_and_centre)
{
    struct scene *sc = test_scene(SCENE);
    struct camera c = sc->cam, pin = sc->cam;
    pin.lens_radius = 0;
    vec3 q = vadd(c.pos, vadd(vscale(c.basis.n, c.focus_dist), vadd(vscale(c.basis.s, 0.3), vscale(c.basis.t, -0.2))));
    double px0, py0, px, py;
    cr_assert(camera_raster(&pin, c.pos, vnorm(vsub(q, c.pos)), &px0, &py0) > 0);
    rng r;
    rng_seed(&r, 5, 0);
    for (int i = 0; i < 1000; i++) {
        double x = 2 * rng_uniform(&r) - 1, y = 2 * rng_uniform(&r) - 1;
        if (x * x + y * y > 1) continue;
        vec3 lens = vadd(c.pos, vadd(vscale(c.basis.s, 0.12 * x), vscale(c.basis.t, 0.12 * y)));
        cr_assert(camera_raster(&c, lens, vnorm(vsub(q, lens)), &px, &py) > 0);
        cr_assert(fabs(px - px0) < 1e-9 && fabs(py - py0) < 1e-9, "%g %g vs %g %g", px, py, px0, py0);
    }
    vec3 d = vnorm(v3(0.1, -0.05, 0.9));
    double a = camera_raster(&c, c.pos, d, &px, &py), b = camera_raster(&pin, c.pos, d, &px0, &py0);
    cr_assert(a == b && px == px0 && py == py0);
    scene_free(sc);
}

static void prefill(struct sampler_writer *w, rng *r)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++)
            w->u[st][i] = rng_uniform(r);
}

/* The inverse camera walk (thesis Alg. 2) returns the lens point and the image position: 20k
 * walks of up to 5 vertices, inverted whole; the numbers of block 0 must come back (max error,
 * the angle number circular) and the replayed walk must retrace the vertices. A lone camera vertex
 * (t = 1) inverts to its lens numbers alone. The image numbers aim at z_1, a single-precision ray
 * hit off the exact ray by ~1e-7 of the scene, so they come back to that precision (as for the
 * pinhole); the lens numbers to double precision. */
Test(thinlens, inverse_camera_walk)
{
    struct scene *sc = test_scene(SCENE);
    struct path_ctx pc = {.sc = sc, .max_length = 4};
    static struct vertex a[MAX_SUBPATH_VERTS], b[MAX_SUBPATH_VERTS];
    static struct sampler_writer U, W;
    sampler_writer_init(&U, 7, 0);
    sampler_writer_init(&W, 8, 0);
    rng r;
    rng_seed(&r, 33, 0);
    const int N = 20000;
    double tol = 1e-4 * fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min))), max_u = 0, max_img = 0;
    int fail = 0, tried = 0;
    for (int i = 0; i < N; i++) {
        prefill(&U, &r);
        struct sampler_replay rp;
        sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])U.u);
        int lone = i % 10 == 0; /* every tenth walk a lone camera vertex */
        int n = walk_camera(&pc, &rp.base, a, lone ? 1 : 5);
        if (!lone && n < 2) continue;
        tried++;
        prefill(&W, &r);
        bool ok = invert_camera(&pc, a, n, 0, &W.base);
        int nu = lone ? 2 : 4;
        for (int k = 0; ok && k < nu; k++) {
            double e = k == 1 ? dist_wrap(W.u[STREAM_CAMERA][k], U.u[STREAM_CAMERA][k])
                              : fabs(W.u[STREAM_CAMERA][k] - U.u[STREAM_CAMERA][k]);
            if (k < 2)
                max_u = fmax(max_u, e);
            else
                max_img = fmax(max_img, e);
        }
        sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])W.u);
        int m = ok ? walk_camera(&pc, &rp.base, b, lone ? 1 : 5) : 0;
        bool same = m >= n;
        for (int j = 0; same && j < n; j++)
            same = vlen(vsub(a[j].p, b[j].p)) <= tol && a[j].prim == b[j].prim;
        fail += !ok || !same;
    }
    fprintf(stderr, "thinlens inverse camera walk: %d of %d fail, max error lens numbers %.3g, image numbers %.3g\n",
            fail, tried, max_u, max_img);
    cr_assert(fail * 2000 <= tried, "%d of %d walks not retraced", fail, tried);
    cr_assert(max_u < 1e-9, "%g", max_u);
    cr_assert(max_img < 1e-5, "%g", max_img);
    scene_free(sc);
}

static void load_fails(const char *camera_extra, const char *path_in_message)
{
    char json[1024], err[1024], file[] = "/tmp/thinlens-XXXXXX";
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"w\", \"type\": \"lambert\", \"albedo\": 0.5}],\n"
             " \"primitives\": [{\"type\": \"quad\", \"bsdf\": \"w\", \"emission\": 1}],\n"
             " \"camera\": {\"type\": \"thinlens\", \"resolution\": 8, %s\n"
             "  \"transform\": {\"position\": [0, 0, 3], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             camera_extra);
    int fd = mkstemp(file);
    cr_assert(fd >= 0);
    cr_assert(write(fd, json, strlen(json)) == (ssize_t)strlen(json));
    close(fd);
    struct scene *s = scene_load(file, err, sizeof err);
    unlink(file);
    if (!path_in_message) {
        cr_assert(s, "%s", err);
        cr_assert(s->cam.lens_radius == 0.001 && s->cam.focus_dist == 1, "Tungsten's defaults");
        scene_free(s);
        return;
    }
    cr_assert_null(s);
    cr_assert(strstr(err, path_in_message), "%s", err);
    cr_assert_null(strchr(err, '\n'), "one line: %s", err);
}

Test(thinlens, loader_fields)
{
    load_fails("", NULL);
    load_fails("\"aperture\": {\"type\": \"disk\"},", "camera.aperture");
    load_fails("\"focus_pivot\": \"mid\",", "camera.focus_pivot");
    load_fails("\"cateye\": 0.2,", "camera.cateye");
    load_fails("\"aperture_size\": -1,", "camera.aperture_size");
    load_fails("\"focus_distance\": 0,", "camera.focus_distance");
}
