/* Inverse random walks, thesis Alg. 2: the numbers that make walk_camera / walk_emitter retrace
 * given vertices. Each block is inverted independently (fixed layout), so a suffix can be
 * re-inverted while the numbers of earlier vertices stay as they are.
 *
 * Closed loop. Alg. 2 inverts block i at the given vertex x_i, aiming at x_{i+1}; but the forward
 * walk scatters from its own hit point, which is a single-precision ray hit off x_i in the last
 * bits (which bits depends on Embree's kernels, so on the CPU: accel.h). Inverted open loop, the
 * walk keeps that offset and grazing bounces (1/cos) and curved surfaces (spheres turn their normal
 * and shading frame with the offset; delta lobes on them double it) grow it at every vertex: on
 * scenes/materials the vertex before a walk's first miss was a median 850x further off than its
 * first hit (README). So each block is inverted at the vertex the walk will actually reach: the
 * block's numbers are replayed through the forward sampling and the ray is traced with walk_hit,
 * exactly as walk_* does. A non-delta vertex then aims from where the walk is, and only one ray's
 * rounding separates each retraced vertex from its target. Costs one ray per inverted block but the
 * last, whose direction nothing follows (PITP inverts one block at a time: no ray, no replay). */
#include "camera/camera.h"
#include "emitter/emitter.h"
#include "path/path.h"

static vec3 dir_to(const struct vertex *a, const struct vertex *b)
{
    double dist2;
    return edge_dir(a, b, &dist2);
}

/* Passes every number put to the caller's writer and keeps the block's copy; then, begun again,
 * replays that copy to the forward sampling functions. */
struct tee {
    struct sampler base;
    struct sampler *w;
    double u[SAMPLER_BLOCK];
    int n;       /* numbers put in the block */
    bool short_; /* the replay read a number the inversion did not put */
};

static double tee_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    struct tee *t = (struct tee *)s;
    if (s->offset < t->n) return t->u[s->offset];
    t->short_ = true;
    return 0.5;
}

static void tee_put(struct sampler *s, enum dim_kind kind, double u)
{
    struct tee *t = (struct tee *)s;
    t->u[s->offset] = u;
    t->n = s->offset + 1;
    sampler_put(t->w, kind, u);
}

static double tee_fresh(struct sampler *s) { return sampler_fresh(((struct tee *)s)->w); }

static const struct sampler_ops tee_ops = {tee_next, tee_put, tee_fresh};

static void tee_begin(struct tee *t, struct sampler *w, int stream, int vertex)
{
    /* u[] is read only below n: not cleared (this runs once per inverted block) */
    t->base = (struct sampler){&tee_ops, 0, 0, 0};
    t->w = w;
    t->n = 0;
    t->short_ = false;
    sampler_begin(&t->base, stream, vertex);
    sampler_begin(w, stream, vertex);
}

static void tee_replay(struct tee *t) { sampler_begin(&t->base, t->base.stream, t->base.vertex); }

/* The numbers of block i that make the BSDF sample at `at` (the walk's vertex i) leave along wo. */
static bool invert_dir(const struct vertex *at, vec3 wo, int i, struct tee *t)
{
    tee_begin(t, t->w, t->base.stream, i);
    return bsdf_invert(&at->bc, frame_to_local(&at->sh, at->wi), frame_to_local(&at->sh, wo), &t->base);
}

/* Block i, first aimed from the walk's vertex `at` at next = v[i+1] (closed loop); cur = v[i].
 * A delta lobe accepts only its own direction, which an offset hit point turns by about twice the
 * offset over the sphere's radius: then its numbers (the lobe) come from v[i] itself, and the walk
 * follows the lobe from `at`. Last, the direction the walk left v[i] in (-v[i+1].wi, exact where
 * the two points are not: a segment of 0.4 mm from the glass sphere to the floor it touches spans
 * 1e-4 rad of hit rounding), if v[i+1] lies on that ray to within a hit point's rounding. */
static bool scatter(const struct vertex *at, const struct vertex *cur, const struct vertex *next, int i, struct tee *t)
{
    if (!at->bc.b || !cur->bc.b) return false;
    if (invert_dir(at, dir_to(at, next), i, t) || invert_dir(cur, dir_to(cur, next), i, t)) return true;
    vec3 wo = vneg(next->wi), e = vsub(next->p, cur->p);
    return next->kind == VK_SURFACE && vdot(e, wo) > 0 && vlen(vcross(e, wo)) <= ray_eps(next->p) &&
           invert_dir(cur, wo, i, t);
}

/* The direction the walk leaves `at` in, from the block just inverted. */
static bool replay_scatter(const struct vertex *at, struct tee *t, enum transport mode, vec3 *d)
{
    tee_replay(t);
    struct bsdf_sample bs;
    if (!bsdf_sample(&at->bc, frame_to_local(&at->sh, at->wi), &t->base, mode, &bs)) return false;
    *d = frame_to_world(&at->sh, bs.wo);
    return true;
}

/* Vertex i of a subpath given as v[0..n-1] and, if `last` is not NULL, last as vertex n: PITP
 * inverts toward a vertex of the other subpath without copying it in. */
static inline const struct vertex *vx(const struct vertex *v, int n, const struct vertex *last, int i)
{
    return i < n ? &v[i] : last;
}

/* The vertex the walk reaches from `at` along d, which the next block is inverted at: the retraced
 * hit when it lies on the target's primitive, else (a miss, another primitive, or a replay that
 * ran short) the target itself, as open-loop inversion would. Written to *buf; returns where it is
 * (the walk's vertex is kept by pointer and copied only here: PITP inverts one block at a time). */
static const struct vertex *follow(const struct scene *sc, const struct vertex *at, bool have_d, vec3 d,
                                   const struct tee *t, const struct vertex *target, struct vertex *buf)
{
    struct vertex hit;
    if (!(have_d && !t->short_ && walk_hit(sc, at, d, &hit) && hit.prim == target->prim)) return target;
    *buf = hit;
    return buf;
}

/* Blocks from.. of a camera subpath of n vertices: v[0..n-1], or v[0..n-2] and *last. */
static bool camera_blocks(const struct path_ctx *pc, const struct vertex *v, int n, const struct vertex *last, int from,
                          struct sampler *w)
{
    int nv = last ? n - 1 : n; /* vertices in v */
    const struct camera *cam = &pc->sc->cam;
    const struct vertex *at = vx(v, nv, last, from);
    struct vertex buf;
    struct tee t;
    /* a lone thin-lens vertex still has its lens point (light tracing's t = 1) */
    if (n == 1 && from == 0 && camera_lens_dims(cam) > 0) {
        tee_begin(&t, w, STREAM_CAMERA, 0);
        return camera_invert_lens(cam, v[0].p, &t.base);
    }
    for (int i = from; i < n - 1; i++) {
        tee_begin(&t, w, STREAM_CAMERA, i);
        vec3 d = v3s(0);
        bool have_d = true, follows = i + 1 < n - 1; /* the last block's direction is not replayed */
        if (i == 0) {
            /* the lens point, then the image position seen from the lens point the walk will
             * have (closed loop: the replayed one, within rounding of v[0]) */
            double px, py, pdf;
            if (!camera_invert_lens(cam, v[0].p, &t.base)) return false;
            tee_replay(&t);
            struct vertex z = v[0];
            z.p = camera_sample_lens(cam, &t.base, &pdf);
            if (!(camera_raster(cam, z.p, dir_to(&z, vx(v, nv, last, 1)), &px, &py) > 0)) return false;
            camera_invert(cam, px, py, &t.base);
            if (!follows) break;
            tee_replay(&t);
            z.p = camera_sample_lens(cam, &t.base, &pdf);
            d = camera_sample_dir(cam, z.p, &t.base, &px, &py, &pdf);
            buf = z;
            at = &buf;
        } else {
            if (!scatter(at, &v[i], vx(v, nv, last, i + 1), i, &t)) return false;
            if (!follows) break;
            have_d = replay_scatter(at, &t, TRANSPORT_RADIANCE, &d);
        }
        at = follow(pc->sc, at, have_d, d, &t, vx(v, nv, last, i + 1), &buf);
    }
    return true;
}

static bool emitter_blocks(const struct path_ctx *pc, const struct vertex *v, int n, const struct vertex *last,
                           int from, struct sampler *w)
{
    int nv = last ? n - 1 : n;
    const struct scene *sc = pc->sc;
    const struct vertex *at = vx(v, nv, last, from);
    struct vertex buf;
    struct tee t;
    for (int i = from; i < n; i++) {
        tee_begin(&t, w, STREAM_EMITTER, i);
        vec3 d = v3s(0);
        bool have_d = true, follows = i + 1 < n - 1; /* the last block's direction is not replayed */
        if (i == 0 && v[0].kind == VK_ENV) {
            if (!emitter_pick_invert(sc, v[0].prim, &t.base) || !env_invert_dir(sc, env_dir(&v[0]), &t.base) ||
                !env_invert_origin(sc, env_dir(&v[0]), v[0].p, &t.base))
                return false;
            if (!follows) continue;
            tee_replay(&t);
            have_d = sample_emitter_vertex(sc, &t.base, &buf);
            at = &buf;
            d = vneg(env_dir(at));
        } else if (i == 0) {
            struct emitter_pos pos = {v[0].p, v[0].ng, 0, v[0].tri};
            if (!emitter_pick_invert(sc, v[0].prim, &t.base) || !emitter_invert_pos(sc, v[0].prim, &pos, &t.base))
                return false;
            if (n > 1 && !emitter_invert_dir(v[0].ng, dir_to(&v[0], vx(v, nv, last, 1)), &t.base)) return false;
            if (!follows) continue;
            double pdf;
            tee_replay(&t);
            have_d = sample_emitter_vertex(sc, &t.base, &buf);
            at = &buf;
            if (have_d) d = emitter_sample_dir(at->ng, &t.base, &pdf);
        } else if (i < n - 1) {
            if (!scatter(at, &v[i], vx(v, nv, last, i + 1), i, &t)) return false;
            if (!follows) continue;
            have_d = replay_scatter(at, &t, TRANSPORT_IMPORTANCE, &d);
        }
        if (follows) at = follow(sc, at, have_d, d, &t, vx(v, nv, last, i + 1), &buf);
    }
    return true;
}

bool invert_camera(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w)
{
    return camera_blocks(pc, v, n, NULL, from, w);
}

bool invert_emitter(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w)
{
    return emitter_blocks(pc, v, n, NULL, from, w);
}

bool invert_step(const struct path_ctx *pc, int stream, const struct vertex *v, int n, const struct vertex *to,
                 struct sampler *w)
{
    return stream == STREAM_CAMERA ? camera_blocks(pc, v, n + 1, to, n - 1, w)
                                   : emitter_blocks(pc, v, n + 1, to, n - 1, w);
}
