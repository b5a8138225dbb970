/* A path's subpaths re-formed from its vertices (path/path_form.h) against the walks and the MIS
 * densities, on every committed scene. Paths: every connection (s, t) with a contribution of
 * independent camera and emitter walks (max length 7).
 *  - Native forms: the emitter form of x_0..x_{s-1} and the camera form of x_k..x_s are the walks'
 *    own subpaths, field for field (beta, pdf_fwd, pdf_rev, wi, frame side, raster position), and a
 *    form must not fail on them. To 1e-2 relative: the walk's directions are the ones it sampled,
 *    the form's the edges between single-precision ray hits, and grazing edges magnify the
 *    difference in cosines (worst 3e-3, on scenes/wall); a wrong factor is off by far more.
 *  - Every other split j: connecting the forms at j gives C_j, and f = C_j p_j is the same for
 *    every technique, so C_i (p_i / p_j) = C_j with the ratio from connect_st's densities at j (a
 *    code that never sees the forms' betas). Checked on the paths where f does not depend on the
 *    technique (no delta vertex, no refraction: pitp_target_may_change's cases), to 1e-6. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <string.h>

#include "path/connect.h"
#include "path/path_form.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

static double rel(double a, double b) { return fabs(a - b) / fmax(1e-300, fmax(fabs(a), fabs(b))); }
static double rel3(rgb a, rgb b) { return fmax(rel(a.x, b.x), fmax(rel(a.y, b.y), rel(a.z, b.z))); }

/* How far form vertex f is from walk vertex w (the fields a walk sets); pdf_rev only if asked. */
static double vertex_diff(const struct vertex *f, const struct vertex *w, bool pdf_rev)
{
    double d = fmax(rel3(f->beta, w->beta), rel(f->pdf_fwd, w->pdf_fwd));
    if (pdf_rev) d = fmax(d, rel(f->pdf_rev, w->pdf_rev));
    d = fmax(d, vlen(vsub(f->wi, w->wi)));
    d = fmax(d, vlen(vsub(f->ng, w->ng)));
    if (f->kind != w->kind || f->flipped != w->flipped || f->front != w->front) d = 1;
    return d;
}

static bool plain_path(const struct vertex *const *x, int k)
{
    for (int i = 0; i <= k; i++)
        if (x[i]->bc.b && (x[i]->delta || x[i]->bc.b->delta_only || x[i]->bc.b->refracts)) return false;
    return true;
}

struct tally {
    int paths, native_fail, cross, cross_fail;
    double native_worst, cross_worst;
};

/* The path of connection (s, t): copies, with the connection's ends not delta (the walk may have
 * gone on from them through a delta lobe; the path does not). */
static int build_path(const struct vertex *y, int s, const struct vertex *z, int t, struct vertex *buf,
                      const struct vertex **x)
{
    int k = s + t - 1;
    for (int i = 0; i <= k; i++) {
        buf[i] = i < s ? y[i] : z[k - i];
        if (i == s - 1 || i == s) buf[i].delta = false;
        x[i] = &buf[i];
    }
    buf[0].delta = buf[k].delta = false;
    return k;
}

static void check_native(const struct path_ctx *pc, const struct vertex *const *x, int k, const struct vertex *y, int s,
                         const struct vertex *z, int t, struct tally *ta)
{
    static struct vertex fy[MAX_SUBPATH_VERTS], fz[MAX_SUBPATH_VERTS];
    if (s >= 1 && !path_emitter_form(pc, x, s, fy)) ta->native_fail++;
    if (!path_camera_form(pc, x, k, t, fz)) ta->native_fail++;
    for (int i = 0; i < s; i++)
        ta->native_worst = fmax(ta->native_worst, vertex_diff(&fy[i], &y[i], i + 2 < s));
    for (int j = 0; j < t; j++)
        ta->native_worst = fmax(ta->native_worst, vertex_diff(&fz[j], &z[j], j + 2 < t));
    if (t >= 2) ta->native_worst = fmax(ta->native_worst, fabs(fz[0].px - z[0].px) + fabs(fz[0].py - z[0].py));
}

/* luminance of C_j and the density ratios at split j (emitter vertex count), from the forms */
static bool split(const struct path_ctx *pc, const struct vertex *const *x, int k, int j, double *c, double *ratios)
{
    static struct vertex fy[MAX_SUBPATH_VERTS], fz[MAX_SUBPATH_VERTS];
    if (j >= 1 && !path_emitter_form(pc, x, j, fy)) return false;
    if (!path_camera_form(pc, x, k, k + 1 - j, fz)) return false;
    struct connection cn;
    if (!connect_st(pc, fy, j, fz, k + 1 - j, k, &cn, ratios)) return false;
    *c = luminance(cn.f);
    return *c > 0;
}

static void check_cross(const struct path_ctx *pc, const struct vertex *const *x, int k, struct tally *ta)
{
    double c[MAX_PATH_LENGTH + 2], r[MAX_PATH_LENGTH + 2][MAX_PATH_LENGTH + 2];
    bool ok[MAX_PATH_LENGTH + 2];
    for (int j = 0; j <= k; j++)
        ok[j] = split(pc, x, k, j, &c[j], r[j]);
    for (int j = 0; j <= k; j++)
        for (int i = 0; i <= k; i++) {
            if (i == j || !ok[i] || !ok[j]) continue;
            ta->cross++;
            double d = rel(c[i] * r[j][i], c[j]);
            ta->cross_worst = fmax(ta->cross_worst, d);
            ta->cross_fail += d > 1e-6;
        }
}

static void check_scene(const char *path, struct tally *ta)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 7};
    static struct vertex y[MAX_SUBPATH_VERTS], z[MAX_SUBPATH_VERTS], buf[MAX_SUBPATH_VERTS];
    const struct vertex *x[MAX_SUBPATH_VERTS];
    struct sampler_independent ind;
    for (int i = 0; i < 8000 && (i < 400 || ta->paths < 300); i++) {
        sampler_independent_init(&ind, 17, (uint64_t)i);
        int nz = walk_camera(&pc, &ind.base, z, 8), ny = walk_emitter(&pc, &ind.base, y, 7);
        for (int t = 1; t <= nz; t++)
            for (int s = 0; s <= ny && s + t - 1 <= 7; s++) {
                struct connection cn;
                if (s + t < 3 || !connect_st(&pc, y, s, z, t, 7, &cn, NULL) || !(luminance(cn.f) > 0)) continue;
                int k = build_path(y, s, z, t, buf, x);
                ta->paths++;
                check_native(&pc, x, k, y, s, z, t, ta);
                if (plain_path(x, k)) check_cross(&pc, x, k, ta);
            }
    }
    scene_free(sc);
}

/* At least 300 paths a scene (ajar's light comes through a door gap: more walks there). */
Test(path, forms_from_vertices_match_the_walks_and_the_mis_densities, .timeout = 300)
{
    cr_assert(test_all_scenes()[0], "no scenes found under scenes/");
    for (const char **s = test_all_scenes(); *s; s++) {
        struct tally ta = {0};
        check_scene(*s, &ta);
        cr_log_info("%s: %d paths, native forms failed %d, worst %.2g; %d cross pairs, %d off, worst %.2g", *s,
                    ta.paths, ta.native_fail, ta.native_worst, ta.cross, ta.cross_fail, ta.cross_worst);
        cr_expect(ta.paths > 50, "%s: only %d paths", *s, ta.paths);
        cr_expect_eq(ta.native_fail, 0, "%s: %d native forms failed", *s, ta.native_fail);
        cr_expect(ta.native_worst < 1e-2, "%s: a native form differs from its walk by %g", *s, ta.native_worst);
        cr_expect_eq(ta.cross_fail, 0, "%s: %d of %d splits disagree (worst %g)", *s, ta.cross_fail, ta.cross,
                     ta.cross_worst);
    }
}
