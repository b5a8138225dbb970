/* Thesis §5.2 and §6.1 on Figure 6.1 decided from bin/fig6_1's runs (fig6_1_claims.h): per claim
 * the worst verdict over the lengths with both cells, errors over the FIG6_1_RUNS runs. */
#include "ch6/fig6_1_claims.h"
#include "common/claims.h"
#include "common/verdict.h"
#include <math.h>
#include <stdio.h>

/* The worse of two verdicts over lengths: the smallest z decides a claim made for every length. */
static void keep_worst(struct verdict *worst, int *at, struct verdict v, int k)
{
    if (*at < 0 || v.zmin < worst->zmin) *worst = v, *at = k;
}

/* Claim c's worst verdict over lengths kmin..K with both cells: (0) MMLT's technique changes below
 * its keeps, (1) PITP's changes within 25 % of its keeps, (2) PITP's changes above MMLT's. */
static int decide(const struct fig6_1_cells *t, int c, int kmin, struct verdict *w)
{
    int at = -1;
    for (int k = kmin; k <= t->K; k++) {
        if (c == 0 && t->have[0][k][0] && t->have[0][k][1]) {
            keep_worst(
                w, &at,
                verdict_pair(t->mean[0][k][1], t->se[0][k][1], t->mean[0][k][0], t->se[0][k][0], -1, FIG6_1_RUNS), k);
        }
        if (c == 1 && t->have[1][k][0] && t->have[1][k][1])
            keep_worst(
                w, &at,
                verdict_similar(t->mean[1][k][1], t->se[1][k][1], t->mean[1][k][0], t->se[1][k][0], 0.25, FIG6_1_RUNS),
                k);
        if (c == 2 && t->have[0][k][1] && t->have[1][k][1]) {
            keep_worst(
                w, &at,
                verdict_pair(t->mean[1][k][1], t->se[1][k][1], t->mean[0][k][1], t->se[0][k][1], +1, FIG6_1_RUNS), k);
        }
    }
    return at;
}

/* Thesis §6.1 on Figure 6.1, every length with both cells; errors over the FIG6_1_RUNS runs. T29-T31
 * are decided over the lengths of the chapter-6 runs (3 and up: they leave direct light out) as the
 * thesis's figure is read beside them; from length 2 on they are the harness's reading. */
static void claims_accept(struct claims *cl, const struct fig6_1_cells *t)
{
    static const struct {
        const char *id;
        int c, kmin;
        const char *claim, *stat, *against;
    } rows[] = {
        {"T29", 0, 3, "small steps in MMLT that change the sampling technique are very likely to be rejected",
         "MMLT small-step acceptance, technique changed vs kept, per length 3 and up (the chapter-6 runs' lengths)",
         "MMLT's technique-keeping steps"},
        {"harness:T29", 0, 2, "small steps in MMLT that change the sampling technique are very likely to be rejected",
         "MMLT small-step acceptance, technique changed vs kept, per length 2 and up",
         "MMLT's technique-keeping steps"},
        {"T31", 1, 3, "the acceptance probabilities in PITP are largely unaffected by technique changes",
         "PITP acceptance ratio changed / kept within ±25 %, per length 3 and up (the chapter-6 runs' lengths)",
         "1 within ±25 %"},
        {"harness:T31", 1, 2, "the acceptance probabilities in PITP are largely unaffected by technique changes",
         "PITP acceptance ratio changed / kept within ±25 %, per length 2 and up", "1 within ±25 %"},
        {"T30", 2, 3, "PITP can change sampling techniques without such a penalty",
         "acceptance of technique-changing small steps, PITP vs MMLT, per length 3 and up (the chapter-6 runs' "
         "lengths)",
         "MMLT's technique changes"},
        {"harness:T30", 2, 2, "PITP can change sampling techniques without such a penalty",
         "acceptance of technique-changing small steps, PITP vs MMLT, per length 2 and up", "MMLT's technique changes"},
    };
    char zs[128], md[256];
    for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
        struct verdict w;
        int k = decide(t, rows[i].c, rows[i].kmin, &w), m = rows[i].c == 0 ? 0 : 1;
        if (k < 0) continue; /* no length with both cells */
        double v = t->mean[m][k][1], se = t->se[m][k][1];
        if (rows[i].c == 1) { /* the ratio and its first-order error */
            double a = t->mean[1][k][1], b = t->mean[1][k][0];
            v = a / b;
            se = ratio_se(a, t->se[1][k][1], b, t->se[1][k][0]);
        }
        snprintf(zs, sizeof zs, "%s=%.2f@%d", (const char *[]){"mmlt-kept", "1x", "mmlt-changed"}[rows[i].c], w.zmin,
                 k);
        snprintf(md, sizeof md, "%s; smallest z = %.1f at length %d", rows[i].against, w.zmin, k);
        claims_row(cl, rows[i].id, "thesis §6.1, Fig. 6.1", rows[i].claim, rows[i].stat, m ? "pitp" : "mmlt", v, se, zs,
                   md, &w);
    }
}

/* Thesis §5.2 on PITP's moves (T23): during a technique change "|j - i| vertices are removed from one
 * subpath and added to the other, which on average is much smaller than k + 1" (the mean |j - i| of
 * the perturbations that change the technique below (k + 1) / 2 at every length: "much" read as at
 * least halving the work of inverting the whole path, the harness's threshold). Beside it the
 * harness's reading of "very likely to retain the current sampling technique": the thesis adds "if
 * it is among the best techniques of the current path", which is not recorded; the row tests the
 * unconditional share of perturbations that change it (below 1/2). Errors over the FIG6_1_RUNS runs. */
static void claims_moves(struct claims *cl, const struct fig6_1_cells *t)
{
    for (int q = 1; q >= 0; q--) {
        struct verdict w;
        int at = -1;
        for (int k = 2; k <= t->K; k++) {
            if (!t->moves[q][k][1]) continue;
            double lim = q ? 0.5 * (k + 1) : 0.5;
            keep_worst(&w, &at, verdict_pair(t->moves[q][k][0], t->moves[q][k][1], lim, 0, -1, FIG6_1_RUNS), k);
        }
        if (at < 0) continue;
        char zs[128], md[256];
        snprintf(zs, sizeof zs, "%s=%.2f@%d", q ? "half-k+1" : "half", w.zmin, at);
        snprintf(md, sizeof md, "%s at every length; smallest z = %.1f at length %d",
                 q ? "below (k + 1) / 2" : "below 1/2", w.zmin, at);
        claims_row(cl, q ? "T23" : "harness:T23", "thesis §5.2",
                   q ? "during a technique change |j - i| is on average much smaller than k + 1"
                     : "PITP is very likely to retain the current technique",
                   q ? "mean |j - i| of PITP's technique-changing perturbations, per length"
                     : "share of all perturbations with j != i, per length",
                   "pitp", t->moves[q][at][0], t->moves[q][at][1], zs, md, &w);
    }
}

/* Thesis §5.2.1 (T22): PITP's technique perturbation keeps the path and picks j in proportion to
 * its MIS weight, so it "is always accepted": its mean acceptance at least 0.99 at every length (an
 * inversion that fails, or a target that differs between techniques, would lower it). */
static void claims_always(struct claims *cl, const struct fig6_1_cells *t)
{
    struct verdict w;
    int at = -1;
    for (int k = 2; k <= t->K; k++) {
        if (!(t->moves[2][k][0] > 0)) continue;
        keep_worst(&w, &at, verdict_pair(t->moves[2][k][0], t->moves[2][k][1], 0.99, 0, +1, FIG6_1_RUNS), k);
    }
    if (at < 0) return;
    char zs[64], md[128];
    snprintf(zs, sizeof zs, "0.99=%.2f@%d", w.zmin, at);
    snprintf(md, sizeof md, "at least 0.99 at every length; smallest z = %.1f at length %d", w.zmin, at);
    claims_row(cl, "T22", "thesis §5.2.1", "PITP's technique perturbation is always accepted",
               "mean acceptance of PITP's perturbations, per length", "pitp", t->moves[2][at][0], t->moves[2][at][1],
               zs, md, &w);
}

char *fig6_1_claims(const struct fig6_1_cells *t, const char *out, const char *scale, char *err, size_t errlen)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig6.1 SCALE=%s", scale);
    claims_begin(&cl, scale, command,
                 "Claims of thesis §5.2 and §6.1 on Fig. 6.1 (ajar, lengths 2-%d; standard errors over %d runs)", t->K,
                 FIG6_1_RUNS);
    claims_accept(&cl, t);
    claims_moves(&cl, t);
    claims_always(&cl, t);
    return claims_finish(&cl, out, err, errlen);
}
