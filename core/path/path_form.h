/* A path's subpaths in the form of any technique, from its vertices alone: the path-space state
 * of Veach's MLT (core/mcmc/docs/veach.md) keeps a path, and each of its mutations needs part of
 * it as an emitter subpath (a prefix) or a camera subpath (a suffix) to extend or connect.
 *
 * The path is x[0] (on an emitter, or at infinity on the environment) .. x[k] (the camera vertex),
 * its vertices in any subpath's form (their kind, frame, bc and delta flag: a delta vertex
 * scatters through a delta lobe toward both neighbours). A form gets the fields a walk would have
 * given the same vertices (path.h): each surface vertex turned toward the side its subpath arrives
 * from (two-sided shading), wi, beta, pdf_fwd, pdf_rev (of all but the last vertex, which the
 * connection sets) and the delta flags. They come from the geometry: a step's direction is the
 * edge's, its throughput and densities the BSDF's eval and pdf (in the subpath's transport mode,
 * with the adjoint shading factor on the emitter side), a delta vertex's the weight and
 * probability of the lobe that reaches the edge's direction (its inverse, then its sampling, on
 * one vertex: no ray). No ray is cast: the edges are the path's, known unoccluded.
 *
 * False when a step is not one a walk could take: a direction on which the shading and geometric
 * normals disagree, a BSDF that cannot produce it (density 0, or no delta lobe within the delta
 * tolerance), no throughput, or no emission. A walk could not have given those vertices either. */
#ifndef PATH_FORM_H
#define PATH_FORM_H

#include "path/path.h"

/* x[0..n-1] (1 <= n <= k) as an emitter subpath y[0..n-1]. */
bool path_emitter_form(const struct path_ctx *pc, const struct vertex *const *x, int n, struct vertex *y);
/* x[k], x[k-1], ..., x[k-n+1] (1 <= n <= k + 1) as a camera subpath z[0..n-1] (z[0].px, py: the
 * raster position of the edge toward x[k-1]). */
bool path_camera_form(const struct path_ctx *pc, const struct vertex *const *x, int k, int n, struct vertex *z);

/* The step out of v[n-1] along unit d as a walk takes it when its sampling gives d (an emitter
 * vertex at n = 1: its emission; a surface: its BSDF in `mode`, with the adjoint factor in
 * importance mode; a delta vertex: its lobe's weight): the throughput *beta the next vertex
 * receives and the solid-angle density *pdf_sa of sampling d there (0 for a delta lobe; the origin
 * disc's area density from the environment); sets v[n-2].pdf_rev. False where a walk could not
 * take the step. Veach's caustic perturbation leaves x_m along a perturbed direction with it. */
bool path_leave(const struct path_ctx *pc, struct vertex *v, int n, vec3 d, enum transport mode, rgb *beta,
                double *pdf_sa);

#endif
