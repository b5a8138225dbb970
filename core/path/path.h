/* Path vertices, random walks (thesis Alg. 1), inverse random walks (Alg. 2) and the
 * multiple-importance weights of every technique of a path (Eq. 5.21-5.25).
 *
 * Camera subpath z_0 (camera), z_1, ...; emitter subpath y_0 (point on an emitter), y_1, ...
 * Technique (s, t) joins y_0..y_{s-1} and z_{t-1}..z_0 into a path of length s + t - 1 segments.
 * Dimension blocks: camera stream block 0 = lens point (thin lens) and image position; block
 * i >= 1 = BSDF sampling at z_i.
 * Emitter stream block 0 = light choice, position, direction; block i >= 1 = BSDF sampling at y_i.
 *
 * Throughput convention: z_0.beta = 1 (the camera's importance equals the density of its lens
 * point and direction, see camera.h; z_0.p is the lens point, z_0.pdf_fwd its area density); y_0.beta = 1 / (pick *
 * pdf_pos); vertex i's beta is the subpath's contribution up to and including the sampling of vertex i. pdf_fwd is the
 * area density of a vertex given its predecessor in its own subpath, pdf_rev the area density of generating it from its
 * successor (0 stands for a Dirac density, which cancels in the MIS ratios as in Veach's thesis). */
#ifndef PATH_H
#define PATH_H

#include "bsdf/bsdf.h"
#include "sampler/sampler.h"
#include "scene/accel.h"
#include "scene/scene.h"

/* VK_ENV is a vertex at infinity on the environment emitter: the end of a camera subpath that left
 * the scene, or the first vertex of an emitter subpath started from the environment. Its direction
 * toward the environment is env_dir(v) = -v->ng; edges to it have no length, densities of it stay
 * in solid angle, and densities of the next vertex from it are the origin disc's times a cosine. */
enum vertex_kind { VK_CAMERA, VK_EMITTER, VK_SURFACE, VK_ENV };

struct vertex {
    /* Small fields first and doubles after, so that no padding creeps in: every walk initialises
     * and MMLT/PITP copy whole subpaths of these, and their size shows in instruction counts. A
     * new field must also be set in vertex_start (below) and surface_from_hit. */
    enum vertex_kind kind;
    bool front;   /* reached from the front (emitting) side of the geometry */
    bool flipped; /* two-sided shading flipped the frame */
    bool delta;   /* the next vertex of its subpath was sampled by a delta lobe */
    int prim, tri;
    vec3 p;
    vec3 ng;            /* geometric normal, flipped to the incoming side for two-sided shading */
    frame sh;           /* shading frame, flipped like ng */
    double b1, b2;      /* barycentrics on triangles */
    struct bsdf_ctx bc; /* bc.b == NULL: no scattering (null BSDF) */
    vec3 wi;            /* unit, toward the previous vertex of its subpath (world) */
    rgb beta;
    double pdf_fwd, pdf_rev;
    double px, py; /* camera vertex: raster position of the primary ray */
};

/* Starts a vertex that is no ray hit (a camera or emitter vertex): every field but p, ng and sh,
 * which the caller sets, is zero, but for its kind, primitive, triangle and front = true. Field by
 * field, in place: a compound literal assigned through a pointer is built in a temporary and
 * copied (GCC cannot rule out that its fields read the target), and memset of the whole vertex
 * is a loop; either cost about 170 instructions per walk's first vertex (MMLT: 2 per mutation). */
static inline void vertex_start(struct vertex *v, enum vertex_kind kind, int prim, int tri)
{
    v->kind = kind;
    v->front = true;
    v->flipped = v->delta = false;
    v->prim = prim;
    v->tri = tri;
    v->b1 = v->b2 = 0;
    v->bc.b = NULL;
    v->bc.albedo = v3s(0);
    v->bc.roughness = 0;
    v->bc.uv[0] = v->bc.uv[1] = 0;
    v->wi = v->beta = v3s(0);
    v->pdf_fwd = v->pdf_rev = v->px = v->py = 0;
}

struct path_ctx {
    const struct scene *sc;
    int max_length; /* segments */
    int min_length; /* segments; shorter paths contribute nothing (0 or 1: none excluded) */
    /* BDPT restricted to one technique (s, t), unweighted, when only_t > 0: each technique alone is
     * an unbiased estimator of the paths of length s + t - 1 (tests, per-technique images). */
    int only_s, only_t;
    /* Weights of the techniques: the balance heuristic, or Kelemen's maximum heuristic (weight 1
     * for the technique of largest density among those that can produce the path, else 0), or the
     * power heuristic (beta = 2). */
    bool max_heuristic, power_heuristic;
};

/* Thesis Alg. 1. Fill `v` (capacity MAX_SUBPATH_VERTS) and return the vertex count.
 * Camera walks stop after max_verts vertices, at a miss, or at a null/absorbing surface. */
int walk_camera(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts);
int walk_emitter(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts);
/* Continues a subpath of n vertices (stream STREAM_CAMERA or STREAM_EMITTER) to at most max_verts,
 * reading blocks n - 1 on: the vertices it adds are those a whole walk would add with the same
 * numbers (v[n-1].delta and v[n-2].pdf_rev are set as the walk sets them). n < 2 walks afresh.
 * PITP's retrace of the vertices a subpath gains (core/mcmc/pitp.c). */
int walk_extend(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, int stream);
/* walk_extend, but a subpath of one vertex keeps it: its direction (the camera's image position, or
 * the emitter's direction) is drawn from the start of block 0, not after the numbers that chose
 * the vertex, so the numbers should be fresh ones (Veach's bidirectional mutation extends a kept
 * endpoint, core/mcmc/veach_bidir.c). Sets v[0].px, py for the camera. */
int walk_extend_from(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, int stream);
/* walk_extend by one vertex, expected to be `to` (NULL: no expectation): where the step's direction
 * points at a surface vertex `to` within float noise, the step takes `to`'s point without casting
 * the ray, so `to` must be a vertex of a path whose segment from v[n-1] is known unoccluded
 * (PITP's retrace of the vertices of its own path, core/mcmc/docs/pitp.md, "Ray-free retrace"). */
int walk_extend_to(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int stream,
                   const struct vertex *to);

/* Whether walk_extend_to(pc, s, v, n, stream, to) would reach the surface vertex `to` within tol
 * (same primitive, point within tol), without writing any vertex and, where the step's direction
 * points at `to` within float noise, without a ray (`to` as for walk_extend_to). n >= 2, or n = 1
 * for the camera stream (its block 0 from the lens point v[0]). PITP's reverse check. */
bool walk_step_reaches(const struct path_ctx *pc, struct sampler *s, const struct vertex *v, int n, int stream,
                       const struct vertex *to, double tol);

/* The emitter vertex y_0 from the current block (light choice, then position or environment
 * direction and origin). */
bool sample_emitter_vertex(const struct scene *sc, struct sampler *s, struct vertex *y);

/* The emitter subpath's first vertex when the light choice is the environment: a direction and a
 * point of the origin disc, from the current block. */
bool sample_env_emitter(const struct scene *sc, double pick, struct sampler *s, struct vertex *y);

/* Thesis Alg. 2: write the numbers that make walk_* reproduce the subpath's vertices from vertex
 * `from` on (from = 0: the whole subpath; from > 0: partial inversion of a suffix, keeping the
 * numbers of the earlier blocks). Returns false when a step is not invertible.
 * Closed loop (path_invert.c): each block is inverted at the vertex the walk will reach, found by
 * replaying the block and tracing its ray (one ray per block), so the walk's rounding does not
 * build up along the subpath. v[from] must therefore be the vertex the walk reaches with the
 * numbers kept (for an MCMC state, its current subpath); v[i].wi is the direction the walk
 * arrived along. */
bool invert_camera(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w);
bool invert_emitter(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w);
/* The last block of a subpath of n >= 1 vertices v[0..n-1] of `stream`, inverted toward vertex
 * `to`: as invert_camera / invert_emitter with `to` as v[n] and from = n - 1, without `to` being
 * copied into the subpath (PITP's extension). */
bool invert_step(const struct path_ctx *pc, int stream, const struct vertex *v, int n, const struct vertex *to,
                 struct sampler *w);

/* The surface vertex a walk reaches from `prev` along unit d (Alg. 1 line 8: the ray, its
 * self-intersection offset and the surface set-up); false on a miss. Inversion retraces through the
 * same function, so it knows the walk's hit points bit for bit. */
bool walk_hit(const struct scene *sc, const struct vertex *prev, vec3 d, struct vertex *out);

/* Surface vertex from a ray hit; `incoming` is the ray direction. */
void surface_from_hit(const struct scene *sc, vec3 origin, vec3 dir, const struct hit *h, struct vertex *v);
/* Texture coordinates of a sphere primitive at the unit world normal n (README, "Textures"). */
void sphere_uv(const struct prim *pr, vec3 n, double uv[2]);

/* The camera walk's vertex at infinity, reached along unit d from point p (beta and pdf_fwd 0: the
 * walk sets them). */
void env_vertex(const struct scene *sc, vec3 p, vec3 d, struct vertex *out);

/* Density of vertex `to` generated from `from` along unit direction d (either orientation) over
 * squared distance dist2: a solid-angle pdf becomes an area density; toward the environment it
 * stays in solid angle; from the environment, pdf is the origin disc's area density. */
double edge_pdf(double pdf, const struct vertex *from, const struct vertex *to, vec3 d, double dist2);
static inline vec3 env_dir(const struct vertex *v) { return vneg(v->ng); }
/* The same vertex within tol: same primitive and position (at infinity, the same direction). What
 * every check that a walk's step reached a given vertex compares; a camera hit on an emitter and
 * the emitter vertex of the same point count as the same vertex. */
static inline bool vertex_same(const struct vertex *a, const struct vertex *b, double tol)
{
    if (a->prim != b->prim) return false;
    if (a->kind == VK_ENV || b->kind == VK_ENV) return a->kind == b->kind && vlen(vsub(a->ng, b->ng)) <= 1e-4;
    return vlen(vsub(a->p, b->p)) <= tol;
}
/* Unit direction from a to b and the squared distance (1 when either end is at infinity). */
vec3 edge_dir(const struct vertex *a, const struct vertex *b, double *dist2);

/* Radiance emitted by vertex v (an emitter surface reached from its front) toward direction w. */
rgb vertex_emission(const struct scene *sc, const struct vertex *v, vec3 w);

/* Veach's adjoint correction for shading normals (thesis of Veach 1997, §5.3), a factor on the BSDF
 * of a vertex of an emitter subpath, which transports importance: with wi toward the previous
 * vertex (the light side) and wo the outgoing direction, |wi.ns| |wo.ng| / (|wi.ng| |wo.ns|).
 * Without it light tracing and every s >= 2 technique see a different BSDF than the path tracer.
 * Exactly 1 where the shading normal is the geometric one. */
double adjoint_shading_factor(const struct vertex *v, vec3 wi, vec3 wo);

/* The factor a refracting vertex carries in radiance mode, (eta on the camera side / eta on the
 * light side)^2 (bsdf_dielectric.c, bsdf_rough_dielectric.c), 1 in importance mode and wherever it
 * does not refract: the ratio of a path's contribution with v on a camera subpath to the same with
 * v on an emitter subpath (PITP's f_j / f_i, Veach's MLT's target). wc, wl: unit directions toward
 * its camera-side and light-side neighbours. */
double vertex_radiance_factor(const struct vertex *v, vec3 wc, vec3 wl);

/* The magnitude of p's coordinates, at least 1: what float rounding of a point near p scales with. */
static inline double coord_scale(vec3 p) { return maxd(fabs(p.z), maxd(fabs(p.y), maxd(fabs(p.x), 1.0))); }
/* Self-intersection offset for rays leaving p. */
double ray_eps(vec3 p);

/* Unoccluded test between two vertices. */
bool visible(const struct scene *sc, const struct vertex *a, const struct vertex *b);

/* MIS. The densities of a full path x_0 (on an emitter) .. x_k (camera): pl[i] = area density of
 * x_i generated from the emitter side, pc[i] from the camera side (0 = Dirac), delta[i] = x_i
 * scatters by a delta lobe. ratios[j] = p_j / p_s for every technique j = 0..k (j light vertices;
 * 0 where technique j cannot produce the path), and the return value is the balance-heuristic
 * weight of technique s. `max_s` limits the techniques considered (a path tracer uses 1). */
struct mis_path {
    int k;
    double pl[MAX_PATH_LENGTH + 2], pc[MAX_PATH_LENGTH + 2];
    bool delta[MAX_PATH_LENGTH + 2];
};
double mis_weights(const struct mis_path *m, int s, int max_s, double *ratios);
/* Rewrites the densities across every chain x_{a+1} .. x_{b-1} of delta vertices (x_a, x_b not
 * delta) to those of the unfolded path, so that the ratio the chain contributes is the one of
 * densities in one measure: the chain's first vertex keeps its solid-angle density from either
 * end (x_a toward x_{a+1}, x_b toward x_{b-1}), the vertices inside are Dirac (1), and the far
 * ends are converted to area over the whole chain: pl(x_b) = cos_b / L^2, pc(x_a) = cos_a / L^2,
 * L the sum of the chain's segment lengths (no falloff from an environment vertex). The
 * per-segment conversion (the walk's, cos/d^2 of the segment at the delta vertex) leaves a factor
 * d_last^2 cos_{a+1} / (d_first^2 cos_{b-1}) per chain instead of cos_b / cos_a in the weights of
 * the techniques on either side, unbiased but wrong. x[i]: vertex i of the path. */
void mis_unfold_delta_chains(struct mis_path *m, const struct vertex *const *x);
/* Maximum heuristic from the same ratios: 1 if technique s has the largest density (ties go to
 * the smallest index), else 0. */
double mis_max_weight(const double *ratios, int k, int s);
/* Veach's power heuristic (beta = 2) from the same ratios (ratios[s] = 1): 1 / sum_j ratios[j]^2. */
double mis_power_weight(const double *ratios, int k);

#endif
