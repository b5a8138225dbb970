/* Technique (s, t) of bidirectional path sampling: the unweighted contribution of joining the
 * first s emitter-subpath vertices with the first t camera-subpath vertices, and the balance
 * heuristic weight from the densities of every technique of the resulting path. */
#ifndef CONNECT_H
#define CONNECT_H

#include "path/path.h"

struct connection {
    rgb f;         /* unweighted contribution, already divided by the sampling density */
    double w;      /* MIS weight of (s, t) among techniques j <= max_s */
    double px, py; /* raster position (t == 1: of the connection; else of z_0's ray) */
};

/* Returns false (and no contribution) when the technique yields nothing for these subpaths.
 * `ratios` (optional, k + 1 entries) receives p_j / p_s for every technique j of the path. */
bool connect_st(const struct path_ctx *pc, const struct vertex *y, int s, const struct vertex *z, int t, int max_s,
                struct connection *out, double *ratios);

#endif
