/* PITP, the path-invariant technique perturbation (see pitp.h; thesis §5.2, Eq. 5.15-5.25, and the
 * optimised inversion of §5.2.2): choice of j in proportion to the MIS weights (Eq. 5.22-5.25),
 * partial inversion with a retrace of each gained vertex, the reverse move's check, the target
 * ratio of refracting paths (Eq. 5.18), and the update of the chain's numbers (technique number:
 * mmlt.h, Eq. 5.6). */
#include "mcmc/pitp.h"
#include "camera/camera.h"
#include "sampling/pick.h"
#include <math.h>

void pitp_scratch_init(struct pitp_scratch *w, const struct scene *sc)
{
    w->tol = 1e-4 * maxd(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min)));
}

/* One block of numbers: written by an inversion, then read back by the forward step that must
 * retrace the vertex inverted toward. Reading anything the inversion did not write is an error. */
struct block_sampler {
    struct sampler base;
    rng *r;
    int stream, vertex, n;
    bool bad;
    double u[SAMPLER_BLOCK];
};

static double blk_next(struct sampler *s, enum dim_kind kind)
{
    struct block_sampler *b = (struct block_sampler *)s;
    (void)kind;
    if (s->stream != b->stream || s->vertex != b->vertex || s->offset >= b->n) {
        b->bad = true;
        return 0.5;
    }
    return b->u[s->offset];
}

static void blk_put(struct sampler *s, enum dim_kind kind, double u)
{
    struct block_sampler *b = (struct block_sampler *)s;
    (void)kind;
    if (b->stream < 0) {
        b->stream = s->stream;
        b->vertex = s->vertex;
    } else if (b->stream != s->stream || b->vertex != s->vertex) {
        b->bad = true;
        return;
    }
    b->u[s->offset] = u;
    if (s->offset + 1 > b->n) b->n = s->offset + 1;
}

static double blk_fresh(struct sampler *s) { return rng_uniform(((struct block_sampler *)s)->r); }
static const struct sampler_ops blk_ops = {blk_next, blk_put, blk_fresh};

static void blk_reset(struct block_sampler *b)
{
    b->stream = -1;
    b->n = 0;
}

/* Blocks of numbers an extension wrote, committed to the chain only when the move is taken. */
struct block_rec {
    int stream, vertex, n;
    double u[SAMPLER_BLOCK];
};

/* The end vertex of a camera subpath that reached an emitter, as the first vertex of an emitter
 * subpath: its emitting-side normal; at infinity the same direction, with a point on the ray that
 * the inversion projects onto the origin disc. */
static struct vertex as_emitter_origin(const struct vertex *z)
{
    struct vertex y = *z;
    if (z->kind != VK_ENV) {
        y.kind = VK_EMITTER;
        y.ng = z->flipped ? vneg(z->ng) : z->ng;
    }
    return y;
}

/* Extends subpath v (n vertices of stream st) through the vertices tgt[0..m-1], one block at a time:
 * invert the block of the last vertex toward the next target, then step the walk with exactly
 * those numbers and require that it reaches the target. An emitter subpath of at most one vertex
 * re-inverts its block 0 whole (light choice, position and direction are one block). */
static bool extend(const struct path_ctx *ctx, int stream, struct vertex *v, int n, const struct vertex *const *tgt,
                   int m, struct block_sampler *blocks, struct block_rec *recs, int *nrec, double tol)
{
    *nrec = 0;
    for (int next = 0; next < m;) {
        blk_reset(blocks);
        blocks->bad = false;
        int used, n_after;
        bool ok;
        if (stream == STREAM_EMITTER && n <= 1) {
            struct vertex y0 = n == 0 ? as_emitter_origin(tgt[next]) : v[0]; /* v[0] is walked afresh */
            const struct vertex *y1 = NULL;
            used = n == 0;
            n_after = 1;
            /* From no vertex, y_0 alone first: the direction is inverted in the frame of the normal
             * the emitter's own sampler gives y_0 (a camera hit's normal can differ from it in the
             * sign of a zero component, which turns the frame), by the next pass with n = 1. */
            if (n == 1 && next + used < m) {
                y1 = tgt[next + used];
                used++;
                n_after = 2;
                /* the environment's origin is a point of the disc on the line through y_1 (for
                 * s = 1 it was any point: a lone y_0 is only connected to along its direction) */
                if (y0.kind == VK_ENV) y0.p = y1->p;
            }
            ok = (y1 ? invert_step(ctx, STREAM_EMITTER, &y0, 1, y1, &blocks->base)
                     : invert_emitter(ctx, &y0, 1, 0, &blocks->base)) &&
                 walk_extend_to(ctx, &blocks->base, v, n_after - 1, STREAM_EMITTER, y1) == n_after && !blocks->bad &&
                 vertex_same(&v[0], &y0, tol) && (!y1 || vertex_same(&v[1], y1, tol));
        } else {
            /* the walk's step must reach the vertex its numbers were inverted toward */
            ok = invert_step(ctx, stream, v, n, tgt[next], &blocks->base) &&
                 walk_extend_to(ctx, &blocks->base, v, n, stream, tgt[next]) == n + 1 && !blocks->bad &&
                 vertex_same(&v[n], tgt[next], tol);
            used = 1;
            n_after = n + 1;
        }
        if (!ok) return false;
        struct block_rec *rec = &recs[(*nrec)++];
        rec->stream = blocks->stream;
        rec->vertex = blocks->vertex;
        rec->n = blocks->n;
        for (int i = 0; i < blocks->n; i++)
            rec->u[i] = blocks->u[i];
        next += used;
        n = n_after;
    }
    return true;
}

/* The reverse move's check: from the new state, the truncated subpath v[0..n_new-1] re-extended
 * toward the vertices it lost, v[n_new..n-1] (the extended subpath now holds them, in its own
 * order, as gained[0..]), must retrace them, as extend would. Asked on the state's own vertices:
 * the new state keeps the truncated subpath bit for bit, and the lost vertices equal the gained ones
 * within the retrace tolerance (extend checked that). So each block is inverted at the lost vertex
 * before it, and the walk's step with those numbers must reach the next (walk_step_reaches), which
 * writes no vertex and, where the step points at the vertex within float noise, casts no ray
 * (docs/pitp.md, "Failed inversions keep detailed balance"). An emitter subpath regrown from at
 * most one vertex (it re-inverts its whole block 0) and a camera subpath that ended at infinity go
 * through extend, on a copy. */
static bool reverse_ok(const struct path_ctx *ctx, int stream, const struct vertex *v, int n_new, int n,
                       const struct vertex *gained, struct pitp_scratch *scratch, struct block_sampler *blocks)
{
    int lost = n - n_new;
    bool surfaces = true;
    for (int vert = n_new; vert < n; vert++)
        surfaces = surfaces && v[vert].kind == VK_SURFACE;
    if ((stream == STREAM_EMITTER && n_new <= 1) || !surfaces) {
        /* extend reads and writes only the last two vertices of the subpath it extends */
        for (int i = n_new >= 2 ? n_new - 2 : 0; i < n_new; i++)
            scratch->rev[i] = v[i];
        for (int vert = 0; vert < lost; vert++)
            scratch->tgt[vert] = &gained[lost - 1 - vert];
        struct block_rec recs[MAX_SUBPATH_VERTS];
        int nrec;
        return extend(ctx, stream, scratch->rev, n_new, scratch->tgt, lost, blocks, recs, &nrec, scratch->tol);
    }
    for (int vert = n_new; vert < n; vert++) {
        blk_reset(blocks);
        blocks->bad = false;
        if (!invert_step(ctx, stream, v, vert, &v[vert], &blocks->base) ||
            !walk_step_reaches(ctx, &blocks->base, v, vert, stream, &v[vert], scratch->tol) || blocks->bad)
            return false;
    }
    return true;
}

/* Marks fresh the numbers a subpath of stream st stops using when it shrinks from n to n_new
 * vertices. A camera subpath of n vertices reads blocks 0..n-2 and, with a single vertex, a thin
 * lens's point at the start of block 0; an emitter subpath blocks 0..n-2 and, with a single
 * vertex, the light choice and position at the start of block 0. */
static void forget_dropped(const struct path_ctx *ctx, struct pss_sampler *pss, int stream, int n, int n_new)
{
    int first = n_new - 1, last = stream == STREAM_EMITTER && n >= 1 ? (n >= 2 ? n - 2 : 0) : n - 2;
    int lens = camera_lens_dims(&ctx->sc->cam);
    if (stream == STREAM_CAMERA && n_new == 1 && lens > 0) {
        for (int offset = lens; offset < SAMPLER_BLOCK; offset++)
            pss_forget(pss, stream, offset);
        first = 1;
    }
    if (stream == STREAM_EMITTER && n_new == 1) {
        /* block 0 keeps what y_0 reads: replay its sampling on the current numbers to count them */
        struct vertex y0;
        sampler_begin(&pss->base, STREAM_EMITTER, 0);
        sample_emitter_vertex(ctx->sc, &pss->base, &y0);
        for (int offset = pss->base.offset; offset < SAMPLER_BLOCK; offset++)
            pss_forget(pss, stream, offset);
        first = 1;
    }
    if (first < 0) first = 0;
    for (int block = first; block <= last; block++)
        for (int offset = 0; offset < SAMPLER_BLOCK; offset++)
            pss_forget(pss, stream, block * SAMPLER_BLOCK + offset);
}

/* Whether the target of the path can change with the technique: through a refracting BSDF (its
 * eta^2 factor is applied in radiance mode only, so f changes when the vertex changes subpath), or
 * a delta vertex (the MIS code counts a Dirac density as 1, but the light side's Dirac sits on the
 * vertex after it and the camera side's on the vertex before it, with different area conversions:
 * the weights sum to one but are not p_j / sum p, and w_j C_j varies with j, by up to 14x on
 * scenes/materials, measured by tests/test_pitp.c). Other paths keep (k + 1) f / sum_l p_l. */
bool pitp_target_may_change(const struct mmlt_path *x)
{
    for (int i = 0; i < x->t + x->s; i++) {
        const struct vertex *v = i < x->t ? &x->cam[i] : &x->emi[i - x->t];
        if (!v->bc.b) continue;
        if (v->bc.b->refracts || v->delta || v->bc.b->delta_only) return true;
    }
    return false;
}

/* f_j / f_i for the path x in technique i's form: the vertices x_l between the two connections
 * change transport mode (l = i..j-1 from radiance to importance when j > i, the reverse when
 * j < i), and only a refraction's factor depends on the mode. With T(i -> j) = w_j, the MIS
 * weights cancel against the Jacobian p_j / p_i (in whatever convention the weights were computed,
 * as long as both moves use the same one), so this is Eq. 5.18's whole ratio. */
static double f_ratio(const struct mmlt_path *x, int sj)
{
    const struct vertex *path_vertex[2 * MAX_SUBPATH_VERTS];
    int k = x->k, si = x->s;
    for (int l = 0; l <= k; l++)
        path_vertex[l] = l < si ? &x->emi[l] : &x->cam[k - l];
    double r = 1;
    int first = si < sj ? si : sj, end = si < sj ? sj : si;
    for (int l = first > 1 ? first : 1; l < end; l++) {
        double dist2;
        double factor = vertex_radiance_factor(path_vertex[l], edge_dir(path_vertex[l], path_vertex[l + 1], &dist2),
                                               edge_dir(path_vertex[l], path_vertex[l - 1], &dist2));
        r = sj > si ? r / factor : r * factor;
    }
    return r;
}

enum pitp_outcome pitp_perturb(const struct path_ctx *ctx, struct pss_sampler *pss, struct mmlt_path *x,
                               struct pitp_scratch *scratch, double u_pick, int *j_out, double *a,
                               struct connection *conn, bool *conn_new, struct nonfinite *nf)
{
    /* the thesis's techniques i and j, as their emitter vertex counts s_old and s_new */
    int k = x->k, s_old = x->s;
    int s_new = pick_weighted(x->ratios, k + 1, u_pick); /* w_j = ratio_j / sum of ratios (Eq. 5.22-5.25) */
    *j_out = s_new;
    *a = 1;
    *conn_new = false;
    if (s_new == s_old) return PITP_SAME;
    int t_new = k + 1 - s_new;
    bool to_emitter = s_new > s_old; /* the emitter subpath gains vertices, the camera subpath loses them */
    int grow_stream = to_emitter ? STREAM_EMITTER : STREAM_CAMERA,
        shrink_stream = to_emitter ? STREAM_CAMERA : STREAM_EMITTER;
    struct vertex *grow = to_emitter ? x->emi : x->cam, *shrink = to_emitter ? x->cam : x->emi;
    int n_grow = to_emitter ? s_old : x->t, n_shrink = to_emitter ? x->t : s_old,
        n_shrink_new = to_emitter ? t_new : s_new;
    int moved = n_shrink - n_shrink_new;
    struct block_sampler blocks; /* u[] is written before it is read (blk_next checks n): not cleared */
    blocks.base = (struct sampler){&blk_ops, 0, 0, 0};
    blocks.r = &pss->r;
    struct block_rec recs[MAX_SUBPATH_VERTS];
    int nrecs;

    /* Eq. 5.18: r = f_j / f_i, 1 unless the path refracts between the two connections; decided
     * first, on the path in i's form, so that a rejection costs no ray */
    *a = mind(1.0, f_ratio(x, s_new));
    if (*a < 1 && !(rng_uniform(&pss->r) < *a)) return PITP_REJECTED;
    bool may_change = pitp_target_may_change(x);
    /* forward: the vertices the shrinking subpath loses, in the growing subpath's order */
    for (int m = 0; m < moved; m++)
        scratch->tgt[m] = &shrink[n_shrink - 1 - m];
    /* what the extension rewrites of the growing subpath: from fewer than 2 vertices it walks
     * afresh, else it sets the last vertex's delta and the one before's reverse density */
    bool afresh = n_grow < 2;
    bool last_delta = afresh ? false : grow[n_grow - 1].delta;
    double before_pdf_rev = afresh ? 0 : grow[n_grow - 2].pdf_rev;
    for (int i = 0; afresh && i < n_grow; i++)
        scratch->save[i] = grow[i];
    bool ok = extend(ctx, grow_stream, grow, n_grow, scratch->tgt, moved, &blocks, recs, &nrecs, scratch->tol);
    /* reverse: from (j, v) the move back to i must succeed as well, or the pair is not symmetric */
    if (ok) ok = reverse_ok(ctx, shrink_stream, shrink, n_shrink_new, n_shrink, grow + n_grow, scratch, &blocks);
    if (ok && may_change) {
        /* the new state's target: the same path, but (k + 1) w_j C_j need not equal the old one */
        const struct vertex *emi_side = to_emitter ? grow : shrink, *cam_side = to_emitter ? shrink : grow;
        double target = 0;
        if (connect_st(ctx, emi_side, s_new, cam_side, t_new, k, conn, scratch->ratios))
            target = luminance(mmlt_contribution(conn, k));
        /* every channel weighs in the luminance: it is finite only when the colour is */
        if (!isfinite(target)) nf->len[k]++;
        *conn_new = isfinite(target) && target > 0;
        if (!*conn_new) ok = false; /* the retraced connection lost the path (occluded in float) */
    }
    if (!ok) {
        for (int i = 0; afresh && i < n_grow; i++)
            grow[i] = scratch->save[i];
        if (!afresh) {
            grow[n_grow - 1].delta = last_delta;
            grow[n_grow - 2].pdf_rev = before_pdf_rev;
        }
        *a = 0;
        return PITP_FAILED;
    }
    /* the move is taken: the gained blocks' numbers, fresh dropped numbers, the technique number */
    for (int rec = 0; rec < nrecs; rec++)
        for (int i = 0; i < recs[rec].n; i++)
            pss_replace(pss, recs[rec].stream, recs[rec].vertex * SAMPLER_BLOCK + i, recs[rec].u[i]);
    forget_dropped(ctx, pss, shrink_stream, n_shrink, n_shrink_new);
    pss_replace(pss, STREAM_TECHNIQUE, 0, mmlt_technique_number(t_new, k, rng_uniform(&pss->r)));
    if (*conn_new) {
        for (int i = 0; i <= k; i++)
            x->ratios[i] = scratch->ratios[i];
    } else {
        double ratio_new = x->ratios[s_new];
        for (int i = 0; i <= k; i++)
            x->ratios[i] /= ratio_new;
    }
    x->s = s_new;
    x->t = t_new;
    return PITP_MOVED;
}
