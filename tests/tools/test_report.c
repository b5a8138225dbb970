/* results/report/index.html (make report) in a real browser, when the report exists: headless
 * Chromium loads it, every image decodes, every local link names a file, a screenshot is written
 * (scripts/report-check.sh). Skipped without the report; without Chromium it fails, since a report
 * that exists is meant to be checked. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

Test(report, loads_in_chromium_with_every_image_and_link, .timeout = 180)
{
    if (access("results/report/index.html", R_OK)) cr_skip_test("no results/report/index.html (make report)");
    int st = system("bash scripts/report-check.sh results/report/index.html");
    cr_assert(WIFEXITED(st), "report-check did not exit");
    cr_assert_neq(WEXITSTATUS(st), 77, "the report exists but Chromium is not installed (apt-get install chromium)");
    cr_assert_eq(WEXITSTATUS(st), 0, "scripts/report-check.sh failed (see its messages)");
}

/* The ledger half of report-check can fail: copies of the page (beside it, so that its relative
 * links still resolve) with one verdict made "maybe", and with one figure's ledger rows removed,
 * must each be refused with the ledger's message. Skipped without a report or without ledger rows. */
static void expect_ledger_refused(const char *edit, const char *message)
{
    char cmd[2048];
    snprintf(
        cmd, sizeof cmd,
        "set -e; d=results/report-ledger-test; rm -rf $d; mkdir -p $d; %s results/report/index.html > $d/index.html; "
        "out=$(bash scripts/report-check.sh $d/index.html 2>&1 || true); rm -rf $d; "
        "printf '%%s\\n' \"$out\" | grep -q '%s'",
        edit, message);
    int st = system(cmd);
    cr_expect(WIFEXITED(st) && WEXITSTATUS(st) == 0, "report-check did not refuse the page edited by `%s` with '%s'",
              edit, message);
}

Test(report, ledger_check_refuses_a_bad_verdict_and_a_missing_figure, .timeout = 300)
{
    if (access("results/report/index.html", R_OK)) cr_skip_test("no results/report/index.html (make report)");
    if (system("grep -q 'class=\"ledger-row\"' results/report/index.html"))
        cr_skip_test("no ledger rows in the report");
    if (system("command -v chromium >/dev/null || command -v chromium-browser >/dev/null"))
        cr_assert_fail("the report exists but Chromium is not installed (apt-get install chromium)");
    expect_ledger_refused("sed -E '0,/class=\"v-[a-z]+\">[a-z]+/s//class=\"v-maybe\">maybe/'",
                          "claims ledger: BAD verdict \"maybe\"");
    /* the first figure that has rows: drop all of them */
    expect_ledger_refused("f=$(grep -o 'data-claims=\"[^\"]*\"' results/report/index.html | head -1); grep -vF \"$f\"",
                          "claims ledger: BAD.*no ledger row for");
}

/* make report hands report.sh its figure targets (REPORT_TARGETS): each must have an entry on the
 * page, whose claims then reach the ledger. The Makefile's own list passes; one target more, without
 * an entry, is refused with its name. report.sh runs in a scratch folder (its scripts and the
 * catalogue, no results), so that the other tests' files cannot touch it; make's parent flags are
 * dropped (no jobserver to inherit). */
Test(report, every_figure_target_has_an_entry, .timeout = 120)
{
    int st = system(
        "set -e; r=$PWD; d=$(mktemp -d); trap 'rm -rf $d' EXIT; "
        "t=$(env -u MAKEFLAGS -u MAKELEVEL make --no-print-directory -n report 2>$d/make.err "
        "| sed -n \"s/^REPORT_TARGETS='\\([^']*\\)'.*/\\1/p\"); "
        "case \" $t \" in *' mmlt-fig9 '*) ;; *) cat $d/make.err >&2; exit 3;; esac; "
        "mkdir $d/w $d/w/results; ln -s $r/scripts $d/w/scripts; cp $r/results/claims-catalogue.csv $d/w/results/; "
        "cd $d/w; REPORT_TARGETS=\"$t\" REPORT_DIR=$d/out bash scripts/report.sh quick >/dev/null 2>$d/err1 "
        "|| { cat $d/err1 >&2; exit 5; }; "
        "if REPORT_TARGETS=\"$t nosuch\" REPORT_DIR=$d/out bash scripts/report.sh quick 2>$d/err >/dev/null; then exit "
        "4; "
        "fi; grep -q 'make nosuch has no entry' $d/err || { cat $d/err >&2; exit 6; }");
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0,
              "status %d (3: no figure targets from make -n report; 5: report.sh failed with them; 4: an unlisted "
              "target accepted; 6: refused without naming it)",
              WIFEXITED(st) ? WEXITSTATUS(st) : -1);
}
