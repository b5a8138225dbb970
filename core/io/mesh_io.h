/* Triangle mesh files: Wavefront .obj (geometry only) and Tungsten's binary .wo3.
 * Data stay in the file's object space; the scene loader transforms them. */
#ifndef MESH_IO_H
#define MESH_IO_H

#include "base/vecmath.h"
#include <stddef.h>
#include <stdio.h>

struct raw_mesh {
    int nverts, ntris;
    vec3 *p;
    vec3 *n;    /* NULL when the file has no normals for some vertex */
    double *uv; /* 2 per vertex, (0, 0) for a corner without vt; NULL when no vertex has one */
    int *tri;   /* 3 per triangle, validated against nverts */
};

/* Dispatches on the extension (.obj or .wo3, case-insensitive). On failure returns false with
 * one line in err that does not repeat the path (the caller names the file and JSON path). */
bool mesh_load(const char *path, struct raw_mesh *m, char *err, size_t errlen);
bool mesh_load_obj(const char *path, struct raw_mesh *m, char *err, size_t errlen);
bool mesh_load_wo3(const char *path, struct raw_mesh *m, char *err, size_t errlen);
/* The same from an open stream or a buffer (the fuzz targets, tests/fuzz/). */
bool mesh_read_obj(FILE *f, struct raw_mesh *m, char *err, size_t errlen);
bool mesh_parse_wo3(const unsigned char *b, size_t len, struct raw_mesh *m, char *err, size_t errlen);
void raw_mesh_free(struct raw_mesh *m);

#endif
