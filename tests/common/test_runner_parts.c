/* experiments/common's runner parts: a table's header and rows come from one column list; the CSV
 * reader finds columns by name (a reordered file reads the same) and names what is missing; an
 * output folder that cannot be made is reported (exit status 2 through outdir_require); the
 * reference cache renders again when the scene's content or a setting changes, and only then. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/util.h"
#include "common/csv_read.h"
#include "common/outdir.h"
#include "common/refcache.h"
#include "common/table.h"
#include "io/image.h"

struct row {
    const char *method;
    int seed;
    double relmse;
};
static double twice(const void *row, int arg) { return arg * ((const struct row *)row)->relmse; }

/* The table's text for one column list and two rows */
static char *table_text(const struct column *cols)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    table_write_header(f, cols);
    table_write_row(f, cols, &(struct row){"mmlt", 3, 0.25});
    table_write_row(f, cols, &(struct row){"pitp", 4, 1.0 / 3});
    fclose(f);
    return buf;
}

Test(common_table, header_and_rows_come_from_one_column_list)
{
    static const struct column cols[] = {COL_STRING(struct row, "method", method),
                                         COL_INT(struct row, "seed", "%d", seed),
                                         COL_DOUBLE(struct row, "relmse", "%.3g", relmse),
                                         COL_COMPUTED("relmse2", "%.2f", twice, 2),
                                         {0}};
    char *t = table_text(cols);
    cr_assert_str_eq(t, "method,seed,relmse,relmse2\nmmlt,3,0.25,0.50\npitp,4,0.333,0.67\n");
    free(t);
    /* the same columns in another order: header and cells move together */
    static const struct column moved[] = {COL_DOUBLE(struct row, "relmse", "%.3g", relmse),
                                          COL_STRING(struct row, "method", method),
                                          COL_INT(struct row, "seed", "%d", seed),
                                          {0}};
    t = table_text(moved);
    cr_assert_str_eq(t, "relmse,method,seed\n0.25,mmlt,3\n0.333,pitp,4\n");
    free(t);
}

Test(common_table, save_writes_metadata_then_header_even_without_rows)
{
    static const struct column cols[] = {COL_STRING(struct row, "method", method), {0}};
    char dir[] = "/tmp/table-XXXXXX", path[64], err[256];
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/t.csv", dir);
    struct table t;
    FILE *f = table_open(&t, cols);
    fprintf(f, "# note\n");
    cr_assert(table_save(&t, path, err, sizeof err), "%s", err);
    char *text = read_whole_file(path);
    cr_assert_str_eq(text, "# note\nmethod\n");
    free(text);
    unlink(path);
    rmdir(dir);
}

static struct csv_file *parse(const char *text, char *err, size_t n)
{
    return csv_parse(xstrdup(text), "t.csv", err, n);
}

/* relmse of method m in c, looked up by name */
static double relmse_of(const struct csv_file *c, const char *m)
{
    char err[256];
    int cm = csv_column(c, "method", err, sizeof err), cr = csv_column(c, "relmse", err, sizeof err);
    cr_assert(cm >= 0 && cr >= 0, "%s", err);
    for (int r = 0; r < c->nrows; r++)
        if (!strcmp(csv_cell(c, r, cm), m)) return csv_number(c, r, cr);
    cr_assert_fail("no row %s", m);
    return 0;
}

Test(common_csv_read, columns_by_name_survive_reordering)
{
    char err[256];
    struct csv_file *a =
        parse("# seconds 1.5\n# b_rse 0.02\nmethod,seed,relmse\nmmlt,1,0.25\npitp,1,0.5\n", err, sizeof err);
    struct csv_file *b = parse("relmse,extra,method\n0.5,x,pitp\n0.25,y,mmlt\n# seconds 2\n", err, sizeof err);
    cr_assert(a && b, "%s", err);
    cr_assert_float_eq(relmse_of(a, "pitp"), 0.5, 0);
    cr_assert_float_eq(relmse_of(b, "pitp"), 0.5, 0);
    cr_assert_float_eq(relmse_of(b, "mmlt"), 0.25, 0);
    double v;
    cr_assert(csv_meta_require(a, "seconds", &v, err, sizeof err) && v == 1.5);
    cr_assert_float_eq(csv_meta_number(a, "b_rse"), 0.02, 0);
    csv_free(a);
    csv_free(b);
}

Test(common_csv_read, a_missing_column_or_key_is_named)
{
    char err[256] = "";
    struct csv_file *c = parse("# seconds 1\nmethod,relmse\nmmlt,0.5\n", err, sizeof err);
    cr_assert(c, "%s", err);
    cr_assert_eq(csv_column(c, "block_spread", err, sizeof err), -1);
    cr_assert_str_eq(err, "t.csv: no column 'block_spread'");
    double v;
    cr_assert(!csv_meta_require(c, "mutations", &v, err, sizeof err));
    cr_assert_str_eq(err, "t.csv: no '# mutations' line");
    cr_assert(isnan(csv_meta_number(c, "mutations")));
    csv_free(c);
    cr_assert_null(parse("a,b\n1,2,3\n", err, sizeof err));
    cr_assert_str_eq(err, "t.csv:2: 3 cells, the header has 2");
}

Test(common_outdir, makes_parents_and_reports_what_it_cannot_make)
{
    char dir[] = "/tmp/outdir-XXXXXX", path[128], err[256];
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/a/b/c", dir);
    cr_assert(outdir_make(path, err, sizeof err), "%s", err);
    cr_assert(outdir_make(path, err, sizeof err), "an existing folder is fine: %s", err);
    struct stat st;
    cr_assert(stat(path, &st) == 0 && S_ISDIR(st.st_mode));
    snprintf(path, sizeof path, "%s/file", dir);
    FILE *f = fopen(path, "w");
    fclose(f);
    snprintf(path, sizeof path, "%s/file/sub", dir);
    cr_assert(!outdir_make(path, err, sizeof err));
    char want[300];
    snprintf(want, sizeof want, "cannot create %s/file: Not a directory", dir);
    cr_assert_str_eq(err, want);
}

Test(common_outdir, require_exits_2_on_a_bad_path, .exit_code = 2) { outdir_require("prog", "/dev/null/sub"); }

/* A refcache_render_fn that counts its calls and writes a 2x1 image of the count */
static struct image *render_count(void *ctx, const char *path, char *err, size_t errlen)
{
    int *calls = ctx;
    struct image *im = img_create(2, 1);
    for (int i = 0; i < 6; i++)
        im->px[i] = ++*calls;
    if (!img_write_exr(im, 1, path, err, errlen)) {
        img_destroy(im);
        return NULL;
    }
    return im;
}

/* The cached value for a scene whose content hashes to scene_hash (scene/scene_hash.h's
 * ckpt_scene_hash in the tools). */
static int get(const char *ref, uint64_t scene_hash, const char *settings, int *calls)
{
    char err[512];
    struct refcache rc = {.path = ref, .scene_hash = scene_hash, .settings = settings};
    struct image *im = refcache_get(&rc, render_count, calls, err, sizeof err);
    cr_assert(im, "%s", err);
    int v = (int)im->px[0];
    img_destroy(im);
    return v;
}

Test(common_refcache, renders_again_when_the_scene_or_a_setting_changes)
{
    char dir[] = "/tmp/refcache-XXXXXX", ref[128];
    cr_assert(mkdtemp(dir));
    snprintf(ref, sizeof ref, "%s/cache/ref.exr", dir); /* its folder is made */
    int calls = 0;
    int first = get(ref, 0x1234, "bdpt spp=4", &calls);
    cr_assert_eq(calls, 6);
    cr_assert_eq(get(ref, 0x1234, "bdpt spp=4", &calls), first, "same scene and settings: the cached image");
    cr_assert_eq(calls, 6);
    get(ref, 0x1234, "bdpt spp=8", &calls);
    cr_assert_eq(calls, 12, "a changed setting renders again");
    get(ref, 0x1234, "bdpt spp=8", &calls);
    cr_assert_eq(calls, 12);
    get(ref, 0x1235, "bdpt spp=8", &calls);
    cr_assert_eq(calls, 18, "a changed scene renders again");
    char key[160];
    refcache_key_path(ref, key, sizeof key);
    char *k = read_whole_file(key);
    cr_assert(k && strstr(k, "bdpt spp=8\n") && !strncmp(k, "reference-v1 scene=", 19), "key: %s", k);
    free(k);
}
