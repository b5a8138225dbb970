/* The regression checks' own tests: run bin/check_stats on two CSVs, and write a copy of a CSV with
 * one row's statistic moved, as a deliberately broken run that the check must reject. */
#ifndef TEST_SUPPORT_CHECK_CSV_H
#define TEST_SUPPORT_CHECK_CSV_H

/* bin/check_stats OPTS BASE CURRENT; returns its exit status (0 pass, 1 a row differs). */
int check_csv_run(const char *opts, const char *base, const char *current);
/* Copies in_path to out with field `field` (0-based; negative: from the end, -1 the last) of the
 * one row that starts with `row` followed by a comma set to `value`. */
void check_csv_perturbed(const char *in_path, const char *out, const char *row, int field, double value);
/* Every check's own test: REPL (an independent run) passes against BASE, and REPL with that row's
 * field set to `value` (a deliberately broken run) fails. */
void check_csv_replicate_and_broken(const char *opts, const char *base, const char *repl, const char *row, int field,
                                    double value);

#endif
