/* The claims catalogue (results/claims-catalogue.csv) and scripts/claims-coverage.sh, which counts
 * how far the ledger's rows answer it. */
#include "support/tmpdir.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static void write_file(const char *dir, const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    cr_assert(f, "%s", path);
    fputs(text, f);
    fclose(f);
}

/* Runs the script with ARGS in dir; its status, its stdout into out. */
static int coverage(const char *dir, const char *args, char *out, size_t n)
{
    char cmd[1024], here[512];
    cr_assert(getcwd(here, sizeof here));
    snprintf(cmd, sizeof cmd, "cd %s && bash %s/scripts/claims-coverage.sh %s 2>err.txt", dir, here, args);
    FILE *p = popen(cmd, "r");
    cr_assert(p);
    size_t len = fread(out, 1, n - 1, p);
    out[len] = 0;
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static const char catalogue[] = "# test catalogue\n"
                                "id,source,where,claim,compares,needs\n"
                                "T1,thesis,§1,a,b,\n"
                                "T2,thesis,§2,a,b,\n"
                                "T3,thesis,§3,a,b,original MLT\n"
                                "C-a,cmlt,§5,a,b,\n";
static const char head[] = "# claims\nid,source,claim,statistic,method,value,se,z_by_method,z_min,verdict,seeds_"
                           "needed,scale,command\n";

/* Counts per source: T1 has a row of its own (holds), T2 only the harness's reading, T3 cannot be
 * tested, C-a has none; with --require-all the missing ones fail; an unknown ID is bad input. */
Test(claims_coverage, counts_rows_readings_and_missing_claims)
{
    char dir[256], out[4096];
    tmpdir_make(dir, sizeof dir, "coverage");
    write_file(dir, "catalogue.csv", catalogue);
    char rows[1024];
    snprintf(rows, sizeof rows,
             "%sT1,s,c,st,m,1,0.1,x=1,3.0,holds,0,quick,make x\n"
             "harness:T2,s,c,st,m,1,0.1,x=1,0.5,undecided,9,quick,make x\n"
             "harness,s,c,st,m,1,0.1,x=1,0.5,undecided,9,quick,make x\n",
             head);
    write_file(dir, "claims.csv", rows);
    cr_assert_eq(coverage(dir, "catalogue.csv claims.csv", out, sizeof out), 0);
    cr_assert(strstr(out, "| thesis | 3 | 1 | 1 rows | 0 rows | 0 rows | 1 | 1 | T2 |"), "%s", out);
    cr_assert(strstr(out, "| cmlt | 1 | 0 | 0 rows | 0 rows | 0 rows | 0 | 0 | C-a |"), "%s", out);
    cr_assert_eq(coverage(dir, "--require-all catalogue.csv claims.csv", out, sizeof out), 1);
    snprintf(rows, sizeof rows, "%sT9,s,c,st,m,1,0.1,x=1,3.0,holds,0,quick,make x\n", head);
    write_file(dir, "bad.csv", rows);
    cr_assert_eq(coverage(dir, "catalogue.csv bad.csv", out, sizeof out), 2);
    tmpdir_remove(dir);
}

/* The committed catalogue: a header, six fields on every row (no comma inside a field), each ID
 * once, each source one of the three papers. */
Test(claims_coverage, the_catalogue_is_well_formed)
{
    FILE *f = fopen("results/claims-catalogue.csv", "r");
    cr_assert(f, "results/claims-catalogue.csv");
    char line[1024], ids[128][16];
    int n = 0;
    bool header = false;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        int commas = 0;
        for (char *c = line; *c; c++)
            commas += *c == ',';
        cr_assert_eq(commas, 5, "not six fields: %s", line);
        if (!header) {
            cr_assert_str_eq(line, "id,source,where,claim,compares,needs\n");
            header = true;
            continue;
        }
        char *src = strchr(line, ',') + 1;
        cr_assert(!strncmp(src, "thesis,", 7) || !strncmp(src, "mmlt,", 5) || !strncmp(src, "cmlt,", 5), "%s", line);
        cr_assert_lt(n, 128);
        snprintf(ids[n], sizeof ids[n], "%.*s", (int)(src - 1 - line), line);
        for (int i = 0; i < n; i++)
            cr_assert_str_neq(ids[i], ids[n], "ID %s twice", ids[n]);
        n++;
    }
    fclose(f);
    cr_assert_geq(n, 56, "%d claims", n);
}

/* Every testable claim of the committed catalogue (no `needs`) has code that writes its row: its ID
 * as a C string ("T21") in a figure's sources under experiments/ or in scripts/. The ledger's rows
 * come from the runs (make figures report, whose coverage table lists a claim without a row); this
 * is the part a test can check without running every figure. */
Test(claims_coverage, every_testable_claim_has_code_that_writes_its_row)
{
    FILE *f = fopen("results/claims-catalogue.csv", "r");
    cr_assert(f, "results/claims-catalogue.csv");
    char line[1024], missing[1024] = "";
    int testable = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || !strncmp(line, "id,", 3)) continue;
        char *needs = strrchr(line, ',');
        cr_assert(needs, "%s", line);
        if (needs[1] != '\n' && needs[1] != 0) continue; /* not reproduced: needs ... */
        char id[32], cmd[256];
        cr_assert_eq(sscanf(line, "%31[^,]", id), 1, "%s", line);
        testable++;
        snprintf(cmd, sizeof cmd, "grep -rqF '\"%s\"' experiments scripts", id);
        if (system(cmd) != 0) snprintf(missing + strlen(missing), sizeof missing - strlen(missing), " %s", id);
    }
    fclose(f);
    cr_assert_gt(testable, 40);
    cr_assert_eq(missing[0], 0, "testable claims without code that writes their row:%s", missing);
}
