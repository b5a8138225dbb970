/* common/run_cache.h: a run's key is its render's options in a canonical order with the build and
 * the scene's content; an entry holds the run's files (not its checkpoint) and is fetched only under
 * exactly its key; and through ch6_equal --run-cache, a second study whose run is the same render,
 * its options written in another order, links the first study's files instead of rendering. */
#include "base/util.h"
#include "common/run_cache.h"
#include "support/tmpdir.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The key of argv into k (4096 bytes). */
static const char *key_of(const struct run_cache *rc, char *const *argv, int argc, char *k)
{
    cr_assert(run_cache_key(rc, argv, argc, k, 4096));
    return k;
}

Test(run_cache, the_key_is_the_options_in_canonical_order)
{
    static char k[4][4096];
    struct run_cache rc = {.dir = "x", .build = 1, .scene = 2};
    char *a[] = {"render", "scenes/a.json", "--method", "mmlt", "--p-large",  "0.2", "--seed",
                 "3",      "--quiet",       "--out",    "o/x",  "--cpu-time", "60"};
    char *b[] = {
        "bin/render", "other/path.json", "--cpu-time", "60",           "--seed", "3", "--out", "p/y", "--p-large",
        "0.2",        "--method",        "mmlt",       "--checkpoint", "60"};
    const char *ka = key_of(&rc, a, 13, k[0]);
    cr_assert_str_eq(ka, key_of(&rc, b, 14, k[1])); /* order, program, scene path, output options */
    cr_assert_str_eq(ka, "run-cache-v1 build=0000000000000001 scene=0000000000000002\n--cpu-time 60\n--method "
                         "mmlt\n--p-large 0.2\n--seed 3\n");
    char *c[] = {"render", "s", "--method", "mmlt", "--p-large", "0.3", "--seed", "3", "--cpu-time", "60"};
    cr_assert_str_neq(ka, key_of(&rc, c, 10, k[1])); /* a value */
    struct run_cache other_build = rc, other_scene = rc;
    other_build.build = 9;
    other_scene.scene = 9;
    cr_assert_str_neq(ka, key_of(&other_build, a, 13, k[1]));
    cr_assert_str_neq(ka, key_of(&other_scene, a, 13, k[1]));
    /* a repeated option: the later one wins in bin/render, so their order is kept */
    char *d1[] = {"render", "s", "--seed", "1", "--seed", "2"}, *d2[] = {"render", "s", "--seed", "2", "--seed", "1"};
    cr_assert_str_neq(key_of(&rc, d1, 6, k[2]), key_of(&rc, d2, 6, k[3]));
    char *flag1[] = {"render", "s", "--one-chain", "--seed", "1"}, *flag2[] = {"render", "s", "--seed", "1"};
    cr_assert_str_neq(key_of(&rc, flag1, 5, k[2]), key_of(&rc, flag2, 4, k[3])); /* a flag without a value */
}

/* An MCMC option given once at its default is the render without it: the figures' "--method mmlt"
 * meets the design studies' "--method mmlt --p-large 0.1" (and PITP's "--pitp-rate 1"); a value
 * that differs, or the option given twice (the later wins), keeps it in the key. */
Test(run_cache, an_option_at_its_default_is_the_render_without_it)
{
    static char k[3][4096];
    struct run_cache rc = {.dir = "x", .build = 1, .scene = 2};
    char *bare[] = {"render", "s", "--method", "pitp", "--seed", "3"};
    char *spelt[] = {"render", "s", "--method", "pitp", "--p-large", "0.10", "--pitp-rate", "1", "--seed", "3"};
    const char *kb = key_of(&rc, bare, 6, k[0]);
    cr_assert_str_eq(kb, key_of(&rc, spelt, 10, k[1]));
    char *other[] = {"render", "s", "--method", "pitp", "--p-large", "0.3", "--seed", "3"};
    const char *ko = key_of(&rc, other, 8, k[1]);
    cr_assert_str_neq(kb, ko);
    /* bin/render renders this at 0.1: its key must be neither 0.3's nor the bare one */
    char *twice[] = {"render", "s", "--method", "pitp", "--p-large", "0.3", "--p-large", "0.1", "--seed", "3"};
    const char *kt = key_of(&rc, twice, 10, k[2]);
    cr_assert_str_neq(kt, ko);
    cr_assert_str_neq(kt, kb);
    char *bad[] = {"render", "s", "--method", "pitp", "--p-large", "0.1x", "--seed", "3"};
    cr_assert_str_neq(kb, key_of(&rc, bad, 8, k[2])); /* not a number: bin/render refuses it, the key keeps it */
}

static void put(const char *dir, const char *name, const char *text)
{
    char p[512], err[512];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    cr_assert(write_text_atomic(p, text, err, sizeof err), "%s", err);
}

static ino_t inode(const char *dir, const char *name)
{
    char p[512];
    struct stat st;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return stat(p, &st) == 0 ? st.st_ino : 0;
}

/* Store links a run's files (not its checkpoint, not a temporary); fetch links them under another
 * prefix; another key, or an entry whose key file says something else, is a miss. */
Test(run_cache, a_stored_run_is_fetched_under_its_key_only)
{
    char dir[256], cache[300], err[512];
    tmpdir_make(dir, sizeof dir, "run-cache");
    snprintf(cache, sizeof cache, "%s/cache", dir);
    struct run_cache rc = {.dir = cache, .build = 1, .scene = 2};
    put(dir, "mmlt-s1-t60.exr", "image");
    put(dir, "mmlt-s1-t60.csv", "# commit x\n");
    put(dir, "mmlt-s1-t60.mixing.csv", "length\n");
    put(dir, "mmlt-s1-t60.ckpt", "state");
    put(dir, "mmlt-s1-t60.exr.tmp77", "half");
    put(dir, "mmlt-s1-t600.exr", "another run");
    char prefix[300], other[300];
    snprintf(prefix, sizeof prefix, "%s/mmlt-s1-t60", dir);
    snprintf(other, sizeof other, "%s/b-s1-t60", dir);
    const char *key = "run-cache-v1 build=1 scene=2\n--method mmlt\n";
    cr_assert_not(run_cache_fetch(&rc, key, other));
    cr_assert(run_cache_store(&rc, key, prefix, err, sizeof err), "%s", err);
    cr_assert(run_cache_store(&rc, key, prefix, err, sizeof err), "a second store of the same key: %s", err);
    cr_assert(run_cache_fetch(&rc, key, other));
    cr_assert_eq(inode(dir, "b-s1-t60.exr"), inode(dir, "mmlt-s1-t60.exr"));
    cr_assert_eq(inode(dir, "b-s1-t60.mixing.csv"), inode(dir, "mmlt-s1-t60.mixing.csv"));
    cr_assert_eq(inode(dir, "b-s1-t60.ckpt"), 0);
    cr_assert_eq(inode(dir, "b-s1-t60.exr.tmp77"), 0);
    cr_assert_eq(inode(dir, "b-s1-t60.0.exr"), 0); /* mmlt-s1-t600.* is another run */
    cr_assert_not(run_cache_fetch(&rc, "run-cache-v1 build=1 scene=2\n--method pitp\n", other));
    /* an entry under the key's hash whose key file differs (a collision) is not this run */
    char cmd[700];
    snprintf(cmd, sizeof cmd, "for k in %s/*/key; do echo other > $k; done", cache);
    cr_assert_eq(system(cmd), 0);
    cr_assert_not(run_cache_fetch(&rc, key, other));
    tmpdir_remove(dir);
}

/* Where no hard link can be made (another file system, forced here), store and fetch copy the
 * files whole, as new files. */
Test(run_cache, without_hard_links_the_files_are_copied_whole)
{
    char dir[256], cache[300], err[512], prefix[300], other[300];
    tmpdir_make(dir, sizeof dir, "run-cache-copy");
    snprintf(cache, sizeof cache, "%s/cache", dir);
    struct run_cache rc = {.dir = cache, .build = 1, .scene = 2};
    static unsigned char bytes[200000]; /* binary, with NULs, longer than one buffer of stdio */
    for (size_t i = 0; i < sizeof bytes; i++)
        bytes[i] = (unsigned char)(i * 2654435761u >> 13);
    snprintf(prefix, sizeof prefix, "%s/pt-s1-spp2", dir);
    snprintf(other, sizeof other, "%s/q-s1-spp2", dir);
    char p[400];
    snprintf(p, sizeof p, "%s.exr", prefix);
    cr_assert(write_bytes_atomic(p, bytes, sizeof bytes, err, sizeof err), "%s", err);
    put(dir, "pt-s1-spp2.csv", "# commit x\n");
    const char *key = "run-cache-v1 build=1 scene=2\n--method pt\n";
    setenv("PSS_TEST_NO_HARDLINK", "1", 1);
    bool stored = run_cache_store(&rc, key, prefix, err, sizeof err), fetched = run_cache_fetch(&rc, key, other);
    unsetenv("PSS_TEST_NO_HARDLINK");
    cr_assert(stored, "%s", err);
    cr_assert(fetched);
    cr_assert_neq(inode(dir, "q-s1-spp2.exr"), inode(dir, "pt-s1-spp2.exr"));
    size_t n = 0;
    snprintf(p, sizeof p, "%s.exr", other);
    void *got = read_file_bytes(p, &n);
    cr_assert(got && n == sizeof bytes && !memcmp(got, bytes, n), "the copy differs (%zu bytes)", n);
    free(got);
    snprintf(p, sizeof p, "%s.csv", other);
    char *csv = read_whole_file(p);
    cr_assert(csv && !strcmp(csv, "# commit x\n"));
    free(csv);
    tmpdir_remove(dir);
}

/* Two ch6_equal studies share a run: the second writes its methods' options in another order and
 * another output folder, and links both runs of its first method from the first study's cache,
 * renders its second (a value differs), and adds it. */
Test(run_cache, a_second_study_links_the_runs_it_shares, .timeout = 120)
{
    char dir[256], cmd[2000];
    tmpdir_make(dir, sizeof dir, "run-cache-study");
    const char *common = BIN_DIR "/ch6_equal --scene scenes/cornell-box/scene.json --seeds 2 --spp 2 "
                                 "--resolution 32x32 --reference-spp 0 --min-length 2 --render-args ''";
    snprintf(cmd, sizeof cmd,
             "%s --out %s/a --methods 'mmlt=--method mmlt --seed-paths 2000 --p-large 0.1' "
             "--run-cache %s/cache > /dev/null 2> %s/a.err",
             common, dir, dir, dir);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    snprintf(cmd, sizeof cmd,
             "%s --out %s/b --methods 'm2=--p-large 0.1 --seed-paths 2000 --method mmlt,m3=--p-large 0.2 "
             "--seed-paths 2000 --method mmlt' --run-cache %s/cache > /dev/null 2> %s/b.err",
             common, dir, dir, dir);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    char p[400];
    snprintf(p, sizeof p, "%s/b.err", dir);
    char *e = read_whole_file(p);
    cr_assert(e && strstr(e, "m2 seed 1, 2 mutations per pixel (from the run cache)") &&
                  strstr(e, "m2 seed 2, 2 mutations per pixel (from the run cache)") &&
                  strstr(e, "m3 seed 1, 2 mutations per pixel\n") && !strstr(e, "m3 seed 1, 2 mutations per pixel ("),
              "%s", e ? e : "(no stderr)");
    free(e);
    char a[300], b[300];
    snprintf(a, sizeof a, "%s/a/runs", dir);
    snprintf(b, sizeof b, "%s/b/runs", dir);
    cr_assert_neq(inode(b, "m2-s1-spp2.exr"), 0);
    cr_assert_eq(inode(a, "mmlt-s1-spp2.exr"), inode(b, "m2-s1-spp2.exr"));
    cr_assert_eq(inode(a, "mmlt-s2-spp2.csv"), inode(b, "m2-s2-spp2.csv"));
    snprintf(cmd, sizeof cmd, "test $(ls -d %s/cache/*/ | wc -l) -eq 4", dir); /* mmlt and m3, two seeds each */
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    tmpdir_remove(dir);
}
