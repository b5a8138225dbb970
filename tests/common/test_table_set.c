/* common/table_set.h: a tool's tables share their metadata lines, land in the output folder under
 * their names, and a family of columns takes its names from one array; a folder that cannot be
 * written is reported, not ignored. */
#include "base/util.h"
#include "common/csv_meta.h"
#include "common/table_set.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const quantity[3] = {"l_x", "l_y", "relmse"};

struct run_row {
    const char *variant;
    long seed;
    double q[3];
};
struct count_row {
    const char *variant;
    int n;
};
static const struct column count_cols[] = {
    COL_STRING(struct count_row, "variant", variant), COL_INT(struct count_row, "n", "%d", n), {0}};

static void meta(FILE *f, const void *ctx) { csv_meta(f, "scale", "%s", (const char *)ctx); }

static char *read_in(const char *dir, const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    char *text = read_whole_file(path);
    cr_assert(text, "%s missing", path);
    unlink(path);
    return text;
}

Test(common_table_set, tables_share_metadata_and_column_families_take_their_names)
{
    struct column run_cols[6] = {COL_STRING(struct run_row, "variant", variant),
                                 COL_LONG(struct run_row, "seed", "%lu", seed)};
    table_columns(run_cols + 2, 3, quantity, COL_D, offsetof(struct run_row, q), sizeof(double), "%.3g");
    run_cols[5] = (struct column){0};
    char dir[] = "/tmp/table-set-XXXXXX", err[256];
    cr_assert(mkdtemp(dir));
    struct table_set ts;
    table_set_open(&ts, 2, (const char *[]){"runs.csv", "counts.csv"}, (const struct column *[]){run_cols, count_cols},
                   meta, "quick");
    table_row(&ts.t[0], &(struct run_row){"iso", 7, {1.5, 2, 0.125}});
    table_row(&ts.t[1], &(struct count_row){"iso", 1});
    cr_assert(table_set_save(&ts, "test", dir, err, sizeof err), "%s", err);
    char *runs = read_in(dir, "runs.csv"), *counts = read_in(dir, "counts.csv");
    cr_assert_str_eq(runs, "# scale quick\nvariant,seed,l_x,l_y,relmse\niso,7,1.5,2,0.125\n");
    cr_assert_str_eq(counts, "# scale quick\nvariant,n\niso,1\n");
    free(runs), free(counts);
    rmdir(dir);
}

Test(common_table_set, an_unwritable_folder_is_reported)
{
    struct table_set ts;
    fprintf(table_set_open_one(&ts, "a.csv", count_cols), "# own metadata\n");
    char err[256] = "";
    cr_assert(!table_set_save(&ts, "test", "/dev/null/sub", err, sizeof err));
    cr_assert(strstr(err, "/dev/null/sub"), "the message names the path: %s", err);
}
