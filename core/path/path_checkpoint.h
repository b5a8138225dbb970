/* Path vertices in checkpoint payloads (io/checkpoint.h). A vertex holds a pointer to its BSDF,
 * the one thing that does not survive a restart: it is stored as the BSDF's index in the scene. */
#ifndef PATH_CHECKPOINT_H
#define PATH_CHECKPOINT_H

#include "io/checkpoint.h"
#include "path/path.h"

void ckpt_put_vertices(struct ckpt_buf *b, const struct scene *sc, const struct vertex *v, int n);
/* False (and short_read set) when the bytes run out or name a BSDF the scene does not have. */
bool ckpt_get_vertices(struct ckpt_buf *b, const struct scene *sc, struct vertex *v, int n);

#endif
