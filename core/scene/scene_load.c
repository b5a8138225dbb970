/* Tungsten JSON scene → struct scene (everything but emitters and accel).
 * Reading order follows Tungsten's Scene::fromJson: media, bsdfs, primitives, camera, integrator,
 * renderer. Every bad input ends in one "FILE: JSON.PATH: expectation" line and a NULL result;
 * nothing is written to stdout. Integrator semantics (TraceBase.cpp, PathTracer.cpp): an emitter
 * hit after `bounce` scattering events, or a light sample taken there (counted as bounce + 1),
 * contributes only while bounce < max_bounces (resp. bounce + 1 < max_bounces) and bounce >= min_bounces.
 * A path of k segments has its emitter hit at bounce = k - 1, so max_bounces is the maximum number of
 * segments and min_bounces + 1 the minimum: max_length = max_bounces, min_length = min_bounces + 1. */
#include "base/util.h"
#include "sampler/sampler.h"
#include "scene/scene_load_internal.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *read_text(const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read: %s", path, strerror(errno));
        return NULL;
    }
    if (!file_is_regular(f)) {
        fclose(f);
        snprintf(err, errlen, "%s: not a regular file", path);
        return NULL;
    }
    size_t cap = 1 << 16, n = 0;
    char *b = xmalloc(cap);
    for (;;) {
        n += fread(b + n, 1, cap - n - 1, f);
        if (n < cap - 1) break;
        if (n > LIMIT_SCENE_BYTES) {
            snprintf(err, errlen, "%s: larger than the limit of %ld MB for a scene file", path,
                     LIMIT_SCENE_BYTES >> 20);
            fclose(f);
            free(b);
            return NULL;
        }
        cap *= 2;
        b = xrealloc(b, cap);
    }
    bool bad = ferror(f);
    fclose(f);
    if (bad) {
        snprintf(err, errlen, "%s: cannot read: I/O error", path);
        free(b);
        return NULL;
    }
    b[n] = '\0';
    if (strlen(b) != n) {
        snprintf(err, errlen, "%s: malformed JSON: the file contains NUL bytes", path);
        free(b);
        return NULL;
    }
    return b;
}

/* "FILE:LINE:COL: malformed JSON near '...'" with the position cJSON stopped at. */
static void json_error(const char *path, const char *text, const char *at, char *err, size_t errlen)
{
    if (!at || at < text) at = text;
    int line = 1, colno = 1;
    for (const char *p = text; p < at && *p; p++) {
        if (*p == '\n') {
            line++;
            colno = 1;
        } else {
            colno++;
        }
    }
    char near[24];
    int k = 0;
    for (const char *p = at; *p && *p != '\n' && k < (int)sizeof near - 1; p++)
        near[k++] = (*p >= 32 && *p < 127) ? *p : '?';
    near[k] = '\0';
    if (k)
        snprintf(err, errlen, "%s:%d:%d: malformed JSON near '%s'", path, line, colno, near);
    else
        snprintf(err, errlen, "%s:%d:%d: malformed JSON (unexpected end of line or file)", path, line, colno);
}

/* ThinlensCamera's fields and defaults (focus_distance 1, aperture_size 0.001, the disc's radius).
 * Its other aperture shapes (an `aperture` texture, `cateye` vignetting) and `focus_pivot` are
 * refused: the lens here is the uniform disc. */
static bool load_thinlens(struct jctx *c, const cJSON *cam, struct camera *out)
{
    if (cJSON_GetObjectItemCaseSensitive(cam, "aperture"))
        return jfail(c, "camera.aperture",
                     "aperture textures are not supported (the aperture is a uniform disc of "
                     "radius aperture_size)");
    if (cJSON_GetObjectItemCaseSensitive(cam, "focus_pivot"))
        return jfail(c, "camera.focus_pivot", "not supported (give focus_distance instead)");
    double focus = 1, radius = 0.001, cateye = 0;
    if (!jget_number(c, cam, "camera", "cateye", false, &cateye)) return false;
    if (cateye != 0) return jfail(c, "camera.cateye", "cat's-eye vignetting is not supported (expected 0)");
    if (!jget_number(c, cam, "camera", "focus_distance", false, &focus)) return false;
    if (!(focus > 0 && focus < 1e30)) return jfail(c, "camera.focus_distance", "expected a positive distance");
    if (!jget_number(c, cam, "camera", "aperture_size", false, &radius)) return false;
    if (!(radius >= 0 && radius < 1e30)) return jfail(c, "camera.aperture_size", "expected a radius >= 0");
    out->lens_radius = radius;
    out->focus_dist = focus;
    return true;
}

static bool load_camera(struct loader *L, const cJSON *cam)
{
    struct jctx *c = &L->c;
    struct camera *out = &L->s->cam;
    if (!cam) return jfail(c, "camera", "missing (expected a pinhole or thinlens camera object)");
    if (!cJSON_IsObject(cam)) return jfail(c, "camera", "expected a camera object");
    const char *type = NULL, *filter = NULL;
    if (!jget_string(c, cam, "camera", "type", true, &type)) return false;
    bool thinlens = strcmp(type, "thinlens") == 0;
    const char *why = refused_feature(REFUSED_CAMERA, type);
    if (why) return jfail(c, "camera.type", "camera type \"%s\" is not supported: %s", type, why);
    if (!thinlens && strcmp(type, "pinhole") != 0)
        return jfail(c, "camera.type", "unsupported camera type \"%s\" (expected \"pinhole\" or \"thinlens\")", type);
    if (cJSON_GetObjectItemCaseSensitive(cam, "medium"))
        return jfail(c, "camera.medium", "participating media are not supported");
    double fov = 60; /* PinholeCamera's default */
    if (!jget_number(c, cam, "camera", "fov", false, &fov)) return false;
    if (!(fov > 0 && fov < 180)) return jfail(c, "camera.fov", "expected degrees in (0, 180)");
    int w = 1000, h = 563; /* Camera's default */
    const cJSON *res = cJSON_GetObjectItemCaseSensitive(cam, "resolution");
    if (res) {
        const char *expect = "expected a positive integer or an array of 2 positive integers";
        const cJSON *e[2] = {res, res};
        if (cJSON_IsArray(res)) {
            if (cJSON_GetArraySize(res) != 2) return jfail(c, "camera.resolution", "%s", expect);
            e[0] = cJSON_GetArrayItem(res, 0);
            e[1] = cJSON_GetArrayItem(res, 1);
        }
        int wh[2];
        for (int i = 0; i < 2; i++) {
            if (!cJSON_IsNumber(e[i])) return jfail(c, "camera.resolution", "%s", expect);
            double d = e[i]->valuedouble;
            if (!(d >= 1 && d <= LIMIT_IMAGE_SIDE && d == floor(d)))
                return jfail(c, "camera.resolution", "%s (at most %d)", expect, LIMIT_IMAGE_SIDE);
            wh[i] = (int)d;
        }
        w = wh[0];
        h = wh[1];
        if ((long)w * h > LIMIT_IMAGE_PIXELS)
            return jfail(c, "camera.resolution", "%dx%d is %ld pixels, above the limit of %ld (8192x8192)", w, h,
                         (long)w * h, LIMIT_IMAGE_PIXELS);
    }
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(cam, "transform");
    if (!t) return jfail(c, "camera.transform", "missing required field (position, look_at, up)");
    mat4 m;
    if (!jval_transform(c, t, "camera.transform", &m)) return false;
    vec3 pos = v3(m.m[0][3], m.m[1][3], m.m[2][3]);
    vec3 fwd = v3(m.m[0][2], m.m[1][2], m.m[2][2]), up = v3(m.m[0][1], m.m[1][1], m.m[2][1]);
    if (!(vlen2(fwd) > 0) || !(vlen2(up) > 0)) return jfail(c, "camera.transform", "degenerate camera transform");
    camera_setup(out, pos, vadd(pos, fwd), up, fov, w, h);
    if (thinlens && !load_thinlens(c, cam, out)) return false;
    /* Tungsten's default is the tent */
    out->filter = FILTER_TENT;
    if (!jget_string(c, cam, "camera", "reconstruction_filter", false, &filter)) return false;
    if (filter && strcmp(filter, "box") == 0)
        out->filter = FILTER_BOX;
    else if (filter && strcmp(filter, "tent") != 0)
        jwarn(c, "camera.reconstruction_filter", "filter \"%s\" is not supported; using tent", filter);
    return true;
}

static bool load_settings(struct loader *L, const cJSON *integ, const cJSON *rend)
{
    struct jctx *c = &L->c;
    struct scene *s = L->s;
    int maxb = 64, minb = 0; /* TraceSettings defaults */
    s->two_sided_shading = true;
    s->spp = 32; /* RendererSettings default */
    if (integ) {
        if (!cJSON_IsObject(integ)) return jfail(c, "integrator", "expected an object");
        if (!jget_int(c, integ, "integrator", "max_bounces", false, 1, LIMIT_BOUNCES, &maxb) ||
            !jget_int(c, integ, "integrator", "min_bounces", false, 0, LIMIT_BOUNCES, &minb) ||
            !jget_bool(c, integ, "integrator", "enable_two_sided_shading", false, &s->two_sided_shading))
            return false;
        if (minb >= maxb)
            return jfail(c, "integrator.min_bounces", "must be less than max_bounces (%d), or no path counts", maxb);
    }
    if (rend) {
        if (!cJSON_IsObject(rend)) return jfail(c, "renderer", "expected an object");
        if (!jget_int(c, rend, "renderer", "spp", false, 1, 1 << 30, &s->spp)) return false;
    }
    if (maxb > MAX_PATH_LENGTH) {
        /* the per-path arrays of the core hold MAX_PATH_LENGTH segments; a longer path carries
         * albedo^64 of the light in any scene that is not a white furnace */
        if (minb >= MAX_PATH_LENGTH)
            return jfail(c, "integrator.min_bounces", "must be less than %d (the renderer's path length limit)",
                         MAX_PATH_LENGTH);
        jwarn(c, "integrator.max_bounces", "%d is above the renderer's limit; paths are capped at %d segments", maxb,
              MAX_PATH_LENGTH);
        maxb = MAX_PATH_LENGTH;
    }
    s->max_length = maxb;
    s->min_length = minb + 1;
    return true;
}

static void grow(vec3 *lo, vec3 *hi, vec3 p)
{
    *lo = v3(fmin(lo->x, p.x), fmin(lo->y, p.y), fmin(lo->z, p.z));
    *hi = v3(fmax(hi->x, p.x), fmax(hi->y, p.y), fmax(hi->z, p.z));
}

static void compute_bbox(struct scene *s)
{
    vec3 lo = v3s(INFINITY), hi = v3s(-INFINITY);
    for (int i = 0; i < s->nprims; i++) {
        const struct prim *p = &s->prims[i];
        if (p->kind == PRIM_SPHERE) {
            grow(&lo, &hi, vsub(p->center, v3s(p->radius)));
            grow(&lo, &hi, vadd(p->center, v3s(p->radius)));
        } else if (p->kind != PRIM_INFINITE_SPHERE) {
            for (int t = 0; t < 3 * p->ntris; t++)
                grow(&lo, &hi, p->p[p->tri[t]]);
        }
    }
    if (lo.x > hi.x) lo = hi = s->cam.pos; /* no finite geometry: a point box at the camera */
    s->bbox_min = lo;
    s->bbox_max = hi;
}

static bool load_root(struct loader *L, const cJSON *root)
{
    struct jctx *c = &L->c;
    struct scene *s = L->s;
    if (!cJSON_IsObject(root)) return jfail(c, "", "expected a JSON object at the top level");
    const cJSON *media = cJSON_GetObjectItemCaseSensitive(root, "media");
    if (media && !(cJSON_IsArray(media) && cJSON_GetArraySize(media) == 0))
        return jfail(c, "media", "participating media are not supported (expected an empty array)");
    L->bsdfs_json = cJSON_GetObjectItemCaseSensitive(root, "bsdfs");
    const cJSON *prims = cJSON_GetObjectItemCaseSensitive(root, "primitives");
    if (!prims) return jfail(c, "primitives", "missing required field");
    if (!cJSON_IsArray(prims)) return jfail(c, "primitives", "expected an array of primitive objects");
    s->nprims = cJSON_GetArraySize(prims);
    /* Top-level and inline bsdfs with their nested ones, plus one shared default. */
    L->bsdf_cap = L->bsdf->slots(L->bsdfs_json) + 1;
    for (const cJSON *p = prims->child; p; p = p->next)
        L->bsdf_cap += cJSON_IsObject(p) ? L->bsdf->slots(cJSON_GetObjectItemCaseSensitive(p, "bsdf")) : 0;
    s->bsdfs = xcalloc(L->bsdf_cap, sizeof *s->bsdfs);
    s->prims = xcalloc(s->nprims ? s->nprims : 1, sizeof *s->prims);
    for (int i = 0; i < s->nprims; i++)
        s->prims[i].bsdf = -1;
    if (!L->bsdf->load_all(L) || !load_primitives(L, prims) || !L->bsdf->check(L)) return false;
    if (!load_camera(L, cJSON_GetObjectItemCaseSensitive(root, "camera"))) return false;
    if (!load_settings(L, cJSON_GetObjectItemCaseSensitive(root, "integrator"),
                       cJSON_GetObjectItemCaseSensitive(root, "renderer")))
        return false;
    compute_bbox(s);
    return true;
}

struct scene *scene_read_model(const char *path, const struct scene_bsdf_reader *bsdfs, char *err, size_t errlen)
{
    char *text = read_text(path, err, errlen);
    if (!text) return NULL;
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithOpts(text, &end, true);
    if (!root) {
        json_error(path, text, end ? end : cJSON_GetErrorPtr(), err, errlen);
        free(text);
        return NULL;
    }
    struct scene *s = xcalloc(1, sizeof *s);
    s->file = xstrdup(path);
    s->env_prim = -1;
    struct loader L = {.c = {.file = path, .err = err, .errlen = errlen}, .s = s, .bsdf = bsdfs, .default_bsdf = -1};
    const char *slash = strrchr(path, '/');
    if (slash) snprintf(L.dir, sizeof L.dir, "%.*s", (int)(slash - path), path);
    if (slash == path) snprintf(L.dir, sizeof L.dir, "/");
    bool ok = load_root(&L, root);
    cJSON_Delete(root);
    free(text);
    if (!ok) {
        scene_model_free(s);
        return NULL;
    }
    return s;
}

void scene_model_free(struct scene *s)
{
    if (!s) return;
    for (int i = 0; i < s->nbsdfs; i++) {
        texture_free(s->bsdfs[i].albedo_tex);
        texture_free(s->bsdfs[i].ratio_tex); /* nested BSDFs: mixed's ratio */
        texture_free(s->bsdfs[i].roughness_tex);
        texture_free(s->bsdfs[i].bump_tex);
    }
    for (int i = 0; s->prims && i < s->nprims; i++) {
        struct prim *p = &s->prims[i];
        free(p->p);
        free(p->n);
        free(p->uv);
        free(p->tri);
        texture_free(p->env_tex);
    }
    free(s->bsdfs);
    free(s->prims);
    free(s->file);
    free(s);
}
