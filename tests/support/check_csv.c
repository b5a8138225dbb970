/* bin/check_stats from the tests (check_csv.h). */
#include "support/check_csv.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

int check_csv_run(const char *opts, const char *base, const char *current)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, BIN_DIR "/check_stats %s %s %s > /dev/null 2>&1", opts, base, current);
    int st = system(cmd);
    cr_assert(WIFEXITED(st), "check_stats did not run: %s", cmd);
    return WEXITSTATUS(st);
}

void check_csv_perturbed(const char *in_path, const char *out, const char *row, int field, double value)
{
    FILE *in = fopen(in_path, "r"), *f = fopen(out, "w");
    cr_assert(in && f, "%s or %s", in_path, out);
    char line[1024];
    size_t rl = strlen(row);
    int hit = 0;
    while (fgets(line, sizeof line, in)) {
        if (strncmp(line, row, rl) || line[rl] != ',') {
            fputs(line, f);
            continue;
        }
        line[strcspn(line, "\n")] = 0;
        char *fld[64];
        int n = 0;
        for (char *p = line; p && n < 64; p = strchr(p, ',') ? strchr(p, ',') + 1 : NULL)
            fld[n++] = p;
        for (int k = 1; k < n; k++)
            fld[k][-1] = 0;
        int at = field < 0 ? n + field : field;
        cr_assert(at >= 0 && at < n, "row %s has no field %d", row, field);
        for (int k = 0; k < n; k++) {
            if (k) fputc(',', f);
            if (k == at)
                fprintf(f, "%.9g", value);
            else
                fputs(fld[k], f);
        }
        fputc('\n', f);
        hit++;
    }
    fclose(in);
    fclose(f);
    cr_assert_eq(hit, 1, "row %s not found once in %s", row, in_path);
}

void check_csv_replicate_and_broken(const char *opts, const char *base, const char *repl, const char *row, int field,
                                    double value)
{
    cr_assert_eq(check_csv_run(opts, base, repl), 0, "%s and %s, two independent runs, disagree", base, repl);
    char tmp[] = "/tmp/check-perturbed-XXXXXX";
    int fd = mkstemp(tmp);
    cr_assert(fd >= 0);
    close(fd);
    check_csv_perturbed(repl, tmp, row, field, value);
    int st = check_csv_run(opts, base, tmp);
    remove(tmp);
    cr_assert_eq(st, 1, "%s: row %s with field %d moved to %g was not detected", repl, row, field, value);
}
