/* Fuzz target: the .obj reader (core/io/mesh_io.c) on the input as a file's bytes. */
#include "fuzz/fuzz.h"
#include "io/mesh_io.h"
#include <stdio.h>

int fuzz_obj(const uint8_t *data, size_t size)
{
    /* fmemopen of an empty buffer fails; a zero-byte read is all the same an empty file */
    static const uint8_t none[1];
    FILE *f = fmemopen((void *)(size ? data : none), size ? size : 1, "rb");
    if (!f) return 0;
    if (!size) fgetc(f);
    struct raw_mesh m;
    char err[512] = "";
    if (mesh_read_obj(f, &m, err, sizeof err)) {
        for (int i = 0; i < 3 * m.ntris; i++)
            if (m.tri[i] < 0 || m.tri[i] >= m.nverts) __builtin_trap();
        raw_mesh_free(&m);
    } else {
        fuzz_check_message(err);
    }
    fclose(f);
    return 0;
}
