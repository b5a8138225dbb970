/* Suite fuzz_replay: every input under tests/data/fuzz/TARGET/ (each once made a target fail, or
 * probes a limit) through the same entry function libFuzzer calls (fuzz.h), here without libFuzzer,
 * so `make test` and `make test-san` keep the bugs found fixed. Suite input_limits: the limits of
 * base/input_limits.h refuse with one line, before allocating. */
#include "fuzz/fuzz.h"
#include "io/mesh_io.h"
#include "io/texels.h"
#include <criterion/criterion.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int replay(const char *target, int (*entry)(const uint8_t *, size_t))
{
    char dir[256];
    snprintf(dir, sizeof dir, "tests/data/fuzz/%s", target);
    DIR *d = opendir(dir);
    cr_assert(d, "%s: missing", dir);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *f = fopen(path, "rb");
        cr_assert(f, "%s: cannot read", path);
        uint8_t *buf = NULL;
        size_t len = 0, cap = 0, k;
        do {
            if (len == cap) buf = realloc(buf, cap = cap ? 2 * cap : 4096);
            k = fread(buf + len, 1, cap - len, f);
            len += k;
        } while (k > 0);
        fclose(f);
        cr_log_info("fuzz_replay: %s (%zu bytes)", path, len);
        entry(buf, len);
        free(buf);
        n++;
    }
    closedir(d);
    return n;
}

Test(fuzz_replay, scene) { cr_expect(replay("scene", fuzz_scene) > 0); }
Test(fuzz_replay, obj) { cr_expect(replay("obj", fuzz_obj) > 0); }
Test(fuzz_replay, wo3) { cr_expect(replay("wo3", fuzz_wo3) > 0); }
Test(fuzz_replay, checkpoint) { cr_expect(replay("checkpoint", fuzz_checkpoint) > 0); }
Test(fuzz_replay, stats_csv) { cr_expect(replay("stats_csv", fuzz_stats_csv) > 0); }
Test(fuzz_replay, texture) { cr_expect(replay("texture", fuzz_texture) > 0); }

Test(input_limits, texture_sizes_refused_from_the_header)
{
    char err[256];
    cr_expect(texels_check_size("t.exr", 16384, 8192, 4, err, sizeof err));
    cr_expect(!texels_check_size("t.exr", 32769, 1, 3, err, sizeof err));
    cr_expect(strstr(err, "t.exr: 32769x1 texels"), "%s", err);
    cr_expect(!texels_check_size("t.exr", 32768, 32768, 3, err, sizeof err));
    cr_expect(!texels_check_size("t.exr", 16384, 8192, 64, err, sizeof err), "34 GB of channels");
    cr_expect(!texels_check_size("t.exr", 0, 4, 3, err, sizeof err));
}

Test(input_limits, wo3_counts_refused_before_allocation)
{
    unsigned char b[32] = {0};
    unsigned long long nv = LIMIT_MESH_ELEMS + 1;
    memcpy(b, &nv, 8);
    struct raw_mesh m;
    char err[256];
    cr_assert(!mesh_parse_wo3(b, sizeof b, &m, err, sizeof err));
    cr_expect(strstr(err, "100000001 vertices, above the renderer's limit of 100000000"), "%s", err);
}
