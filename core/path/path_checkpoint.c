/* Path vertices in and out of checkpoint payloads (path_checkpoint.h). */
#include "path/path_checkpoint.h"
#include <stdint.h>

/* The BSDF pointer as its index in the scene plus one (0: none). Slots past a path's end hold
 * whatever an earlier path left, or nothing ever written; they are never read, and store 0. */
void ckpt_put_vertices(struct ckpt_buf *b, const struct scene *sc, const struct vertex *v, int n)
{
    uintptr_t lo = (uintptr_t)sc->bsdfs, hi = (uintptr_t)(sc->bsdfs + sc->nbsdfs);
    for (int i = 0; i < n; i++) {
        struct vertex x = v[i];
        uintptr_t p = (uintptr_t)v[i].bc.b;
        x.bc.b = (const struct bsdf *)(p >= lo && p < hi ? (p - lo) / sizeof *sc->bsdfs + 1 : 0);
        CKPT_PUT(b, x);
    }
}

bool ckpt_get_vertices(struct ckpt_buf *b, const struct scene *sc, struct vertex *v, int n)
{
    for (int i = 0; i < n; i++) {
        if (!CKPT_GET(b, v[i])) return false;
        uintptr_t k = (uintptr_t)v[i].bc.b;
        if (k > (uintptr_t)sc->nbsdfs) {
            b->short_read = true;
            return false;
        }
        v[i].bc.b = k ? &sc->bsdfs[k - 1] : NULL;
    }
    return true;
}
