/* Reading a claims.csv in tests (claims_rows.h). */
#include "support/claims_rows.h"
#include "base/util.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

char *claims_rows_read(const char *dir)
{
    char path[256];
    snprintf(path, sizeof path, "%s/claims.csv", dir);
    char *csv = read_whole_file(path);
    cr_assert(csv, "cannot read %s", path);
    return csv;
}

const char *claims_rows_verdict(const char *csv, const char *id, const char *has)
{
    static const char *const words[] = {"holds", "contradicted", "undecided"};
    size_t n = strlen(id);
    for (const char *l = csv; *l;) {
        const char *end = strchr(l, '\n');
        size_t len = end ? (size_t)(end - l) : strlen(l);
        char line[2048];
        snprintf(line, sizeof line, "%.*s", (int)len, l);
        if (!strncmp(line, id, n) && line[n] == ',' && strstr(line, has))
            for (int w = 0; w < 3; w++) {
                char pat[32];
                snprintf(pat, sizeof pat, ",%s,", words[w]);
                if (strstr(line, pat)) return words[w];
            }
        l += len + (end != NULL);
    }
    return NULL;
}
