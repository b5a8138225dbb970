/* bin/ch6_equal's report (ch6_equal.h): OUT/NAME.md, the table at the largest budget with the
 * error-vs-time slope, and the claims (ch6_claims.h), both also on stdout. */
#include "ch6/ch6_equal.h"
#include "ch6/ch6_stats.h"
#include "common/die.h"
#include "common/text_out.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The slope of log mean relMSE against log budget over e's budgets */
static double relmse_slope(const struct ch6_equal *e, int mi)
{
    double bx[CH6_MAX_BUDGETS], by[CH6_MAX_BUDGETS];
    for (int bi = 0; bi < e->nb; bi++) {
        double v[CH6_MAX_SEEDS], se;
        for (int s = 0; s < e->seeds; s++)
            v[s] = e->R[mi][bi][s].q[Q_RELMSE];
        mean_se(v, e->seeds, &by[bi], &se);
        bx[bi] = e->budgets[bi];
    }
    return ch6_loglog_slope(bx, by, e->nb);
}

/* The mixing diagnostics' cell: the largest R-hat and the ESS per second (means over the seeds), the
 * share of stuck chains, and how many of the seeds' runs warn; a dash for a method without chains. */
static const char *mixing_cell(const double (*q)[2], char *cell, size_t n)
{
    if (isnan(q[Q_RHAT][0])) return "—";
    snprintf(cell, n, "%.3f / %.3g / %.0f %%%s", q[Q_RHAT][0], q[Q_ESS_PER_S][0], 100 * q[Q_STUCK][0],
             q[Q_MIX_WARN][0] > 0 ? " ⚠" : "");
    return cell;
}

/* One budget has no slope: its cell is a dash, not "nan". */
static const char *slope_cell(const struct ch6_equal *e, int mi, char *cell, size_t n)
{
    if (e->nb < 2) return "—";
    snprintf(cell, n, "%.2f", relmse_slope(e, mi));
    return cell;
}

/* A statistic a method does not have (the non-zero shares and the seed pass of BDPT or PT) is a dash. */
static const char *stat_cell(const double q[2], double scale, const char *fmt, char *cell, size_t n)
{
    if (isnan(q[0])) return "—";
    snprintf(cell, n, fmt, scale * q[0], scale * q[1]);
    return cell;
}

static void table_rows(const struct ch6_equal *e, FILE *f)
{
    char cell[96], slope[32], nz[64], lnz[64], brse[32];
    for (int mi = 0; mi < e->nm; mi++) {
        if (!e->ms[mi].available) {
            fprintf(f, "| %s | not available in this build | | | | | | | | | | | |\n", e->ms[mi].name);
            continue;
        }
        const double(*q)[2] = e->sum[mi];
        fprintf(
            f,
            "| %s | %.4g ± %.2g | %.4g ± %.2g | %.3g ± %.2g | %.3g ± %.2g | %.2f ± %.2f | %.0f ± %.0f | %s | %s | %s "
            "| %.0f %% | %s | %s |\n",
            e->ms[mi].name, q[Q_RELMSE][0], q[Q_RELMSE][1], q[Q_BLOCK_MEDIAN][0], q[Q_BLOCK_MEDIAN][1], q[Q_SPREAD][0],
            q[Q_SPREAD][1], q[Q_BLUR8][0], q[Q_BLUR8][1], q[Q_CORRLEN][0], q[Q_CORRLEN][1], q[Q_MPS][0], q[Q_MPS][1],
            stat_cell(q[Q_NONZERO], 1, "%.4f ± %.4f", nz, sizeof nz),
            stat_cell(q[Q_LARGE_NONZERO], 1, "%.4f ± %.4f", lnz, sizeof lnz), slope_cell(e, mi, slope, sizeof slope),
            /* rounded first, so that a share just below zero prints as 0, not -0 */
            round(100 * (1 - q[Q_RELMSE_SCALED][0] / q[Q_RELMSE][0])) + 0.0,
            stat_cell(q[Q_B_RSE], 100, "%.2f %%", brse, sizeof brse), mixing_cell(q, cell, sizeof cell));
    }
}

static void write_markdown(const struct ch6_equal *e)
{
    struct text_out t;
    FILE *f = text_out_open(&t);
    char path[4200], err[4400];
    fprintf(f,
            "**%s**, %g %s per run (%d threads), %d seeds, paths of length >= %d, reference %d spp BDPT; mean ± "
            "standard error over seeds\n\n",
            e->name, e->T,
            e->spp > 0 ? "mutations per pixel"
            : e->wall  ? "s (wall clock)"
                       : "s (CPU seconds per thread)",
            e->threads, e->seeds, e->minlen, e->refspp);
    fprintf(
        f,
        "| method | relMSE | median block relMSE | block-relMSE spread (CV, %dx%d) | error share after 8x8 blur | "
        "error correlation length (px) | mutations/s | non-zero proposals | large-step non-zero | relMSE slope vs "
        "time | normalisation's share of relMSE | seed pass rel. s.e. | mixing: R-hat / ESS per s / stuck chains (⚠: "
        "R-hat > 1.01, ESS < 100 or a stuck chain in a run) |\n",
        e->blk, e->blk);
    fprintf(f, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    table_rows(e, f);
    snprintf(path, sizeof path, "%s/%s.md", e->out, e->name);
    if (!text_out_commit(&t, path, err, sizeof err)) die(DIE_RUNTIME, e->prog, "%s", err);
    fputs(t.buf, stdout);
    text_out_free(&t);
}

static void write_claims(const struct ch6_equal *e)
{
    char names[CH6_MAX_METHODS][64], err[1024];
    bool have[CH6_MAX_METHODS];
    double cm[CH6_MAX_METHODS][Q_COUNT], cs[CH6_MAX_METHODS][Q_COUNT];
    for (int mi = 0; mi < e->nm; mi++) {
        snprintf(names[mi], sizeof names[mi], "%.63s", e->ms[mi].name); /* method names are short */
        have[mi] = e->ms[mi].available;
        for (int q = 0; q < Q_COUNT; q++)
            cm[mi][q] = have[mi] ? e->sum[mi][q][0] : NAN, cs[mi][q] = have[mi] ? e->sum[mi][q][1] : NAN;
    }
    struct ch6_claims_in ci = {.scene = e->name,
                               .source = e->source,
                               .command = e->command,
                               .scale = e->scale,
                               .out = e->out,
                               .budget = e->T,
                               .unit = e->spp > 0 ? "mutations per pixel" : "s",
                               .seeds = e->seeds,
                               .minlen = e->minlen,
                               .study = e->study,
                               .methods = e->nm,
                               .name = (const char(*)[64])names,
                               .have = have,
                               .mean = (const double(*)[Q_COUNT])cm,
                               .se = (const double(*)[Q_COUNT])cs};
    char *claims = ch6_write_claims(&ci, err, sizeof err);
    if (!claims) die(DIE_RUNTIME, e->prog, "%s", err);
    fputs(claims, stdout);
    free(claims);
}

void ch6_report(const struct ch6_equal *e)
{
    write_markdown(e);
    write_claims(e);
}
