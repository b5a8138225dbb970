/* Fuzz target: the .wo3 reader (core/io/mesh_io.c) on the input as a file's bytes. */
#include "fuzz/fuzz.h"
#include "io/mesh_io.h"

int fuzz_wo3(const uint8_t *data, size_t size)
{
    struct raw_mesh m;
    char err[512] = "";
    if (mesh_parse_wo3(data, size, &m, err, sizeof err)) {
        for (int i = 0; i < 3 * m.ntris; i++)
            if (m.tri[i] < 0 || m.tri[i] >= m.nverts) __builtin_trap();
        raw_mesh_free(&m);
    } else {
        fuzz_check_message(err);
    }
    return 0;
}
