/* results/report/index.html (make report) in a real browser, when the report exists: headless
 * Chromium loads it, every image decodes, every local link names a file, a screenshot is written
 * (scripts/report-check.sh). Skipped without the report; without Chromium it fails, since a report
 * that exists is meant to be checked. */
#include <criterion/criterion.h>
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
