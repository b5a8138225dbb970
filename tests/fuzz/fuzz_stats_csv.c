/* Fuzz target: check_stats' CSV reader (experiments/tools/stats_csv.c), the way the tool calls it:
 * the first column as the key, then the rows with and without a count column. */
#include "fuzz/fuzz.h"
#include "tools/stats_csv.h"
#include <stdio.h>

static void read_as(const uint8_t *data, size_t size, const char *count)
{
    FILE *f = fmemopen((void *)data, size, "r");
    if (!f) return;
    char key[STATS_NAME], err[512] = "";
    struct stats_table t;
    struct stats_cols cols = {.key = {key}, .nkeys = 1, .mean = "mean", .se = "se", .count = count};
    if (!stats_csv_first_column(f, "fuzz.csv", key, err, sizeof err)) {
        fuzz_check_message(err);
    } else {
        rewind(f);
        if (stats_csv_read(f, "fuzz.csv", &cols, &t, err, sizeof err))
            stats_table_free(&t);
        else
            fuzz_check_message(err);
    }
    fclose(f);
}

int fuzz_stats_csv(const uint8_t *data, size_t size)
{
    if (!size) return 0; /* fmemopen refuses an empty buffer */
    read_as(data, size, NULL);
    read_as(data, size, "runs");
    return 0;
}
