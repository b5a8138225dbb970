/* The chapter-6 claims and their verdicts (ch6_claims.h). */
#include "ch6/ch6_claims.h"
#include "common/claims.h"
#include <math.h>
#include <string.h>

#define MAX_METHODS 16
#define PITP_RATE_SCALED "relMSE without the normalisation's part (image scaled to the reference's mean)"

/* Each claim is tested as the source states it, against whom it names (`against`: a space-separated
 * list; NULL every other method of the run, where the study's runs are those the source compares),
 * in the studies whose runs are its setting. */
static const struct claim {
    const char *id; /* results/claims-catalogue.csv */
    const char *text, *method;
    int sign; /* +1: the method's value is the largest; -1: the smallest */
    enum ch6_q q;
    const char *statistic;
    const char *against;
    const char *source;  /* NULL: the run's --source */
    bool direct;         /* the source's setting includes direct light: harness:ID for runs without it */
    const char *studies; /* the bin/ch6_equal studies whose runs test it (space-separated) */
} claims[] = {
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_RELMSE, "relMSE", NULL, NULL, false, "equal-time"},
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_BLOCK_MEDIAN, "median block relMSE (firefly-robust)", NULL, NULL,
     false, "equal-time"},
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_TRIMMED, "relMSE without the 0.1% largest pixel errors", NULL, NULL,
     false, "equal-time"},
    {"T33", "at equal time PSSMLT produces fewer samples than MMLT", "pssmlt", -1, Q_MPS, "mutations per second",
     "mmlt", NULL, false, "equal-time"},
    /* "In contrast, PITP ...": MMLT's artifacts against PITP, "such as on the couch in Figure 6.2 (red
     * inset), the floor in Figure 6.3 (red inset), or the golden teapot in Figure 6.4 (yellow inset)":
     * in the inset named (--named-inset); over the whole image the rows are the harness's */
    {"T34", "(2) MMLT shows streaky or splotchy artifacts (against PITP)", "mmlt", +1, Q_INSET_BLUR8,
     "error share surviving an 8x8 blur, in the inset the thesis names", "pitp", NULL, false, "equal-time"},
    {"T34", "(2) MMLT shows streaky or splotchy artifacts (against PITP)", "mmlt", +1, Q_INSET_SPREAD,
     "block-relMSE spread (CV), in the inset the thesis names", "pitp", NULL, false, "equal-time"},
    {"harness:T34", "(2) MMLT shows streaky or splotchy artifacts over the whole image (against PITP)", "mmlt", +1,
     Q_BLUR8, "error share surviving an 8x8 blur", "pitp", NULL, false, "equal-time"},
    {"harness:T34", "(2) MMLT shows streaky or splotchy artifacts over the whole image (against PITP)", "mmlt", +1,
     Q_SPREAD, "block-relMSE spread (CV)", "pitp", NULL, false, "equal-time"},
    {"harness:T34", "(2) MMLT shows streaky or splotchy artifacts over the whole image (against PITP)", "mmlt", +1,
     Q_CORRLEN, "error correlation length (pixels)", "pitp", NULL, false, "equal-time"},
    {"T35", "(3) PITP's noise is more uniform than MMLT's", "pitp", -1, Q_INSET_SPREAD,
     "block-relMSE spread (CV), in the inset the thesis names", "mmlt", NULL, false, "equal-time"},
    {"T35", "(3) PITP's noise is more uniform than MMLT's", "pitp", -1, Q_SPREAD, "block-relMSE spread (CV)", "mmlt",
     NULL, false, "equal-time"},
    {"T35", "(3) PITP's noise is more uniform than MMLT's", "pitp", -1, Q_BLUR8, "error share surviving an 8x8 blur",
     "mmlt", NULL, false, "equal-time"},
    {"T36", "PITP improves upon previous work (MMLT, PSSMLT) in each scene", "pitp", -1, Q_RELMSE, "relMSE",
     "mmlt pssmlt", "thesis §7", false, "equal-time"},
    {"T36", "PITP improves upon previous work (MMLT, PSSMLT) in each scene", "pitp", -1, Q_BLOCK_MEDIAN,
     "median block relMSE (firefly-robust)", "mmlt pssmlt", "thesis §7", false, "equal-time"},
    /* thesis §4.3: low large-step acceptance "is especially the case in Multiplexed MLT" */
    {"T12", "low large-step acceptance is especially a problem of MMLT", "mmlt", -1, Q_LARGE_NONZERO,
     "large-step proposals with a contribution (fraction)", "pssmlt", "thesis §4.3", false, "equal-time"},
    /* thesis §4.3, §7.1 (make hybrid-study): MMLT large steps for short paths and MCTLS for long ones
     * "could perform better" than either; said at the thesis's MCTLS cost, without small steps
     * (bin/fig4_6 writes that T20 row): with small steps and the harness's cheaper MCTLS the rows are
     * the harness's */
    {"harness:T20", "a hybrid (MMLT large steps short, MCTLS long) performs better than either, with small steps",
     "hybrid4", -1, Q_RELMSE, "relMSE", "mmlt mctls", "thesis §4.3, §7.1", false, "hybrid"},
    {"harness:T20", "a hybrid (MMLT large steps short, MCTLS long) performs better than either, with small steps",
     "hybrid6", -1, Q_RELMSE, "relMSE", "mmlt mctls", "thesis §4.3, §7.1", false, "hybrid"},
    {"harness:T20", "a hybrid (MMLT large steps short, MCTLS long) performs better than either, with small steps",
     "hybrid8", -1, Q_RELMSE, "relMSE", "mmlt mctls", "thesis §4.3, §7.1", false, "hybrid"},
    /* MMLT paper §5, Fig. 4 (make mmlt-equal): "MMLT is less noisy than both" BDPT and PSSMLT */
    {"M-b", "MMLT is less noisy than BDPT and PSSMLT at equal time", "mmlt", -1, Q_RELMSE, "relMSE", "bdpt pssmlt",
     "MMLT paper §5, Fig. 4", false, "mmlt-equal mmlt-fig4"},
    /* MMLT paper Figs. 1 and 6 (make mmlt-fig4): the door scene against Veach's MLT, whose mutations
     * here are the bidirectional mutation and the lens and caustic perturbations (core/mcmc/docs/veach.md) */
    {"M-a", "on the door scene PSSMLT is noisy overall (against MLT and MMLT)", "pssmlt", +1, Q_RELMSE, "relMSE",
     "mlt mmlt", "MMLT paper Fig. 1", false, "mmlt-fig4"},
    /* "suboptimal sampling on glossy surfaces results in distracting artifacts. Our Multiplexed MLT
     * ... renders glossy surfaces more accurately" (Fig. 1), "shows splotchy artifacts on glossy
     * surfaces" (§5), "its convergence is slower on glossy surfaces. MMLT results in more uniform
     * convergence across different regions" (Fig. 6): on the pixels whose first hit is glossy
     * (glossy_mask.h), against MMLT */
    {"M-a", "original MLT is less accurate than MMLT on glossy surfaces", "mlt", +1, Q_GLOSSY_RELMSE,
     "relMSE on glossy surfaces", "mmlt", "MMLT paper Fig. 1", false, "mmlt-fig4"},
    {"M-a", "original MLT shows (splotchy) artifacts on glossy surfaces (against MMLT)", "mlt", +1, Q_GLOSSY_BLUR8,
     "error share surviving an 8x8 blur, on glossy surfaces", "mmlt", "MMLT paper Fig. 1", false, "mmlt-fig4"},
    {"M-c", "original MLT is splotchy on glossy surfaces (against MMLT)", "mlt", +1, Q_GLOSSY_BLUR8,
     "error share surviving an 8x8 blur, on glossy surfaces", "mmlt", "MMLT paper Fig. 6", false, "mmlt-fig4"},
    {"M-c", "original MLT converges more slowly on glossy surfaces than elsewhere, MMLT more uniformly across them",
     "mlt", +1, Q_GLOSSY_RATIO, "log10 relMSE on glossy surfaces / elsewhere", "mmlt", "MMLT paper Fig. 6", false,
     "mmlt-fig4"},
    /* the same over the whole image, glossy and diffuse: the harness's */
    {"harness:M-a", "original MLT shows artifacts (against MMLT; whole image, glossy and diffuse)", "mlt", +1, Q_BLUR8,
     "error share surviving an 8x8 blur", "mmlt", "MMLT paper Fig. 1", false, "mmlt-fig4"},
    {"harness:M-c", "original MLT is splotchy (against MMLT; whole image, glossy and diffuse)", "mlt", +1, Q_BLUR8,
     "error share surviving an 8x8 blur", "mmlt", "MMLT paper Fig. 6", false, "mmlt-fig4"},
    {"M-c", "MMLT converges more uniformly than original MLT", "mmlt", -1, Q_SPREAD, "block-relMSE spread (CV)", "mlt",
     "MMLT paper Fig. 6", false, "mmlt-fig4"},
    /* MMLT paper Fig. 9 (make mmlt-fig9): the door scene without glossy materials (Lambertian and specular ones) */
    {"M-i", "on a diffuse door original MLT beats MMLT", "mlt", -1, Q_RELMSE, "relMSE", "mmlt", "MMLT paper Fig. 9",
     false, "mmlt-fig9"},
    {"M-i", "on a diffuse door MMLT beats PSSMLT", "mmlt", -1, Q_RELMSE, "relMSE", "pssmlt", "MMLT paper Fig. 9", false,
     "mmlt-fig9"},
    /* make fused: Veach's perturbations fused into MMLT and PITP through the inverse (Otsu et al.
     * 2017, not one of the three sources: the harness's rows). Their paper: MLT wins on a door
     * scene, MMLT on a caustic one, the fused chain is robust on both; and the thesis's §7.1 asks
     * whether "other perturbations ... can make use of such an approach" */
    {"harness", "on the door scene original MLT beats MMLT (Otsu et al. 2017)", "mlt", -1, Q_RELMSE, "relMSE", "mmlt",
     "Otsu et al. 2017, §6", false, "fused-door"},
    {"harness", "on the caustic scene MMLT beats original MLT (Otsu et al. 2017)", "mmlt", -1, Q_RELMSE, "relMSE",
     "mlt", "Otsu et al. 2017, §6", false, "fused-caustic"},
    {"harness", "fused perturbations are robust: MMLT+fused beats MMLT (Otsu et al. 2017)", "mmlt-fused", -1, Q_RELMSE,
     "relMSE", "mmlt", "Otsu et al. 2017, §6", false, "fused-door fused-caustic"},
    {"harness", "fused perturbations are robust: MMLT+fused beats original MLT (Otsu et al. 2017)", "mmlt-fused", -1,
     Q_RELMSE, "relMSE", "mlt", "Otsu et al. 2017, §6", false, "fused-door fused-caustic"},
    {"harness", "other perturbations through the inverse help PITP: PITP+fused beats PITP (thesis §7.1's question)",
     "pitp-fused", -1, Q_RELMSE, "relMSE", "pitp", "thesis §7.1", false, "fused-door fused-caustic"},
    /* thesis Fig. 3.4 (make bdpt-pt): BDPT has the lower variance at equal samples */
    {"T37", "BDPT has lower variance than path tracing at equal samples", "bdpt", -1, Q_RELMSE, "relMSE", "pt",
     "thesis §3.5, Fig. 3.4", false, "background"},
    /* thesis Fig. 3.3 (make mis-robust, scenes/veach-mis): path tracing and next-event estimation
     * "show sampling deficiencies for certain material-emitter combinations. MIS is robust over all
     * combinations": no region where the combination fails, so its worst region's error is the lowest
     * (per region the better technique alone can beat it: robust is not best everywhere). The whole
     * image's relMSE is the harness's reading. */
    {"T38", "MIS of path tracing and next-event estimation is robust over all material-emitter combinations", "mis", -1,
     Q_BLOCK_MAX, "log10 of the largest block relMSE (the worst region)", "bsdf nee", "thesis Fig. 3.3", false, "mis"},
    {"harness:T38", "MIS of path tracing and next-event estimation has the lowest error over the whole image", "mis",
     -1, Q_RELMSE, "relMSE", "bsdf nee", "thesis Fig. 3.3", false, "mis"},
    /* MMLT paper §6 (make mmlt-equal): no weighting function found beats the balance heuristic in
     * MMLT's target; against the power heuristic (beta = 2). The source's "not better" is the ratio
     * row below; the balance heuristic significantly better is the harness's stronger reading */
    {"harness:M-l", "no weighting function beats the balance heuristic in MMLT's target (against the power heuristic)",
     "mmlt", -1, Q_RELMSE, "relMSE", "mmlt-power", "MMLT paper §6", false, "mmlt-equal"},
    /* MMLT paper §4 (make mmlt-design): b_k estimated progressively "is less likely to miss rare
     * bounces" than once at the start; the image's mean is where a missed bounce shows. The paper's
     * renders include direct light: its setting is mmlt-design's ajar-direct run (paths of 1 to 8
     * segments); the chapter-6 scenes' runs (paths of 3 and more) are harness:M-j, harness:M-k */
    {"M-j", "b_k estimated progressively is less likely to miss rare bounces than once at the start",
     "mmlt-progressive", -1, Q_NORM_ERR, "|image mean / reference mean - 1|", "mmlt", "MMLT paper §4", true,
     "mmlt-design"},
    {"M-j", "b_k estimated progressively is less likely to miss rare bounces than once at the start",
     "mmlt-progressive", -1, Q_B_IMAGE_RSE, "the normalisation's relative standard error", "mmlt", "MMLT paper §4",
     true, "mmlt-design"},
    /* MMLT paper §4: "a separate Markov chain for each path length ... is more efficient" than one
     * chain over all lengths */
    {"M-k", "one chain per path length is more efficient than one chain over all lengths", "mmlt", -1, Q_RELMSE,
     "relMSE", "mmlt-one-chain", "MMLT paper §4", true, "mmlt-design"},
    {"M-k", "one chain per path length is more efficient than one chain over all lengths", "mmlt", -1, Q_BLOCK_MEDIAN,
     "median block relMSE (firefly-robust)", "mmlt-one-chain", "MMLT paper §4", true, "mmlt-design"},
    /* the harness's readings: the splotchiest and the most uniform of the three chapter-6 methods */
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_CORRLEN, "error correlation length (pixels)",
     "pssmlt pitp", NULL, false, "equal-time"},
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_BLUR8, "error share surviving an 8x8 blur",
     "pssmlt pitp", NULL, false, "equal-time"},
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_SPREAD, "block-relMSE spread (CV)", "pssmlt pitp",
     NULL, false, "equal-time"},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_SPREAD, "block-relMSE spread (CV)", "pssmlt mmlt",
     NULL, false, "equal-time"},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_BLUR8, "error share surviving an 8x8 blur",
     "pssmlt mmlt", NULL, false, "equal-time"},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_CORRLEN, "error correlation length (pixels)",
     "pssmlt mmlt", NULL, false, "equal-time"},
    /* 11.81 % of PSSMLT's samples against 29.75 % of MMLT's on the door scene, direct light included:
     * a PSSMLT sample is one connection, as in MMLT (the paper's numbers are those of the per-connection
     * count); a PSSMLT proposal with any contributing connection is the harness's reading */
    {"harness:M-d", "(4) MMLT has more non-zero samples than PSSMLT", "mmlt", +1, Q_NONZERO,
     "non-zero fraction per proposal", "pssmlt", "MMLT paper §5", false, "equal-time ratio"},
    {"M-d", "(4) MMLT has more non-zero samples than PSSMLT", "mmlt", +1, Q_NONZERO_CONN,
     "non-zero fraction per connection", "pssmlt", "MMLT paper §5", true, "equal-time ratio"},
    /* make pitp-rate: the harness's own question, how often PITP should move the technique (P: the
     * probability that a small step is preceded by it; p1 the thesis's, p0.05 Tungsten's
     * reversible-jump rate) */
    {"harness", "the thesis's P = 1 is the best rate", "p1", -1, Q_RELMSE, "relMSE", NULL,
     "harness: how often should PITP move the technique?", false, "pitp-rate"},
    {"harness", "the thesis's P = 1 is the best rate", "p1", -1, Q_BLOCK_MEDIAN, "median block relMSE (firefly-robust)",
     NULL, "harness: how often should PITP move the technique?", false, "pitp-rate"},
    {"harness", "a rate as low as the reversible-jump default (0.05) loses the gain (vs P = 1)", "p0.05", +1, Q_RELMSE,
     "relMSE", "p1", "harness: how often should PITP move the technique?", false, "pitp-rate"},
    {"harness", "a rate as low as the reversible-jump default (0.05) loses the gain (vs P = 1)", "p0.05", +1,
     Q_BLOCK_MEDIAN, "median block relMSE (firefly-robust)", "p1", "harness: how often should PITP move the technique?",
     false, "pitp-rate"},
    /* Every P of a seed shares that seed's seed pass, so its normalisation error is the same for all
     * of them and, where it dominates (the living room at 100 000 seed paths), hides what P changes:
     * the same comparisons with it divided out */
    {"harness", "the thesis's P = 1 is the best rate", "p1", -1, Q_RELMSE_SCALED, PITP_RATE_SCALED, NULL,
     "harness: how often should PITP move the technique?", false, "pitp-rate"},
    {"harness", "a rate as low as the reversible-jump default (0.05) loses the gain (vs P = 1)", "p0.05", +1,
     Q_RELMSE_SCALED, PITP_RATE_SCALED, "p1", "harness: how often should PITP move the technique?", false, "pitp-rate"},
};

bool ch6_listed(const char *list, const char *word)
{
    size_t n = strlen(word);
    for (const char *p = strstr(list, word); p; p = strstr(p + 1, word))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || !p[n])) return true;
    return false;
}

/* The claim's ID for this run: harness:ID when the source's setting has direct light and the run
 * leaves it out. */
static const char *claim_id(const struct claim *cl, const struct ch6_claims_in *in, char *buf, size_t len)
{
    if (!cl->direct || in->minlen <= 2) return cl->id;
    snprintf(buf, len, "harness:%s", cl->id);
    return buf;
}

/* The note on a row whose runs' chains mix poorly (issue 45: R-hat > 1.01, ESS < 100 or a stuck
 * chain in any seed's run at the largest budget) among the methods with use[i]: into buf, "" for
 * none. */
static const char *mixing_flag(const struct ch6_claims_in *in, const bool *use, char *buf, size_t n)
{
    buf[0] = 0;
    for (int i = 0; i < in->methods; i++) {
        if (!use[i] || !(in->mean[i][Q_MIX_WARN] > 0)) continue;
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "%s%s", l ? " " : "chains mix poorly (R-hat; ESS; stuck): ", in->name[i]);
    }
    return buf;
}

static int find(const struct ch6_claims_in *in, const char *method)
{
    for (int i = 0; i < in->methods; i++)
        if (in->have[i] && !strcmp(in->name[i], method)) return i;
    return -1;
}

/* Claims of a ratio of two methods' means: a / b within ±25 % of `target` (side 0), or one-sided, at
 * least 0.75 `target` (side +1: "not much better") or at most 1.25 `target` (side -1: "not worse"). */
static const struct ratio_claim {
    const char *id, *source, *text, *statistic, *a, *b;
    enum ch6_q q;
    double target;
    int side;
    bool direct;         /* as struct claim's */
    const char *studies; /* as struct claim's */
} ratio_claims[] = {
    /* MMLT paper §5: "an improvement of approximately 2.5 times" in the share of non-zero samples */
    {"harness:M-e", "MMLT paper §5", "MMLT's share of non-zero samples is about 2.5 times PSSMLT's",
     "non-zero fraction per proposal", "mmlt", "pssmlt", Q_NONZERO, 2.5, 0, false, "equal-time ratio"},
    {"M-e", "MMLT paper §5", "MMLT's share of non-zero samples is about 2.5 times PSSMLT's",
     "non-zero fraction per connection", "mmlt", "pssmlt", Q_NONZERO_CONN, 2.5, 0, true, "equal-time ratio"},
    /* thesis §4.2 (make cdc-ch6): "in other scenes the effect of CDC is usually subtle" */
    {"T11", "thesis §4.2", "CDC's effect is usually subtle in other scenes (relMSE within ±25 %)", "relMSE",
     "pssmlt-cdc", "pssmlt", Q_RELMSE, 1, 0, false, "cdc"},
    /* MMLT paper §5, Fig. 4: "PSSMLT does not improve the efficiency much over BPT" at equal time:
     * one-sided, a PSSMLT far worse than BDPT does not contradict it */
    {"M-b", "MMLT paper §5, Fig. 4", "PSSMLT does not improve much on BDPT at equal time", "relMSE", "pssmlt", "bdpt",
     Q_RELMSE, 1, +1, false, "mmlt-equal"},
    /* MMLT paper §6: "we did not find a weighting function with better performance than the balance
     * heuristic": the power heuristic not better, the balance heuristic's relMSE at most 1.25x its */
    {"M-l", "MMLT paper §6",
     "no weighting function beats the balance heuristic in MMLT's target (against the power heuristic)", "relMSE",
     "mmlt", "mmlt-power", Q_RELMSE, 1, -1, false, "mmlt-equal"},
};

/* The ratio claims whose two methods ran; the ratio's first-order standard error. */
static void ratio_rows(struct claims *out, const struct ch6_claims_in *in, const char *study)
{
    for (size_t k = 0; k < sizeof ratio_claims / sizeof *ratio_claims; k++) {
        const struct ratio_claim *rc = &ratio_claims[k];
        if (!ch6_listed(rc->studies, study)) continue;
        int ai = find(in, rc->a), bi = find(in, rc->b);
        if (ai < 0 || bi < 0 || isnan(in->mean[ai][rc->q]) || !(in->mean[bi][rc->q] > 0)) continue;
        double a = in->mean[ai][rc->q], b = in->mean[bi][rc->q];
        double r = a / b, rse = ratio_se(a, in->se[ai][rc->q], b, in->se[bi][rc->q]);
        char zs[64], md[128], idbuf[64], stat[160];
        struct verdict v;
        if (rc->side) {
            double bound = (rc->side > 0 ? 0.75 : 1.25) * rc->target;
            v = verdict_pair(r, rse, bound, 0, rc->side, in->seeds);
            snprintf(zs, sizeof zs, "%gx=%.2f", bound, v.zmin);
            snprintf(md, sizeof md, "at %s %g (z = %.1f)", rc->side > 0 ? "least" : "most", bound, v.zmin);
        } else {
            v = verdict_similar(r, rse, rc->target, 0, 0.25, in->seeds);
            snprintf(zs, sizeof zs, "%gx=%.2f", rc->target, v.zmin);
            snprintf(md, sizeof md, "%g within ±25 %% (z = %.1f)", rc->target, v.zmin);
        }
        snprintf(stat, sizeof stat, "%s, %s / %s", rc->statistic, rc->a, rc->b);
        const struct claim c = {.id = rc->id, .direct = rc->direct};
        bool use[MAX_METHODS] = {false};
        char flag[256];
        use[ai] = use[bi] = true;
        out->flag = mixing_flag(in, use, flag, sizeof flag);
        claims_row(out, claim_id(&c, in, idbuf, sizeof idbuf), rc->source, rc->text, stat, rc->a, r, rse, zs, md, &v);
        out->flag = NULL;
    }
}

char *ch6_write_claims(const struct ch6_claims_in *in, char *err, size_t errlen)
{
    struct claims out;
    claims_begin(&out, in->scale, in->command, "Claims on %s at %g %s per run, %d seeds", in->scene, in->budget,
                 in->unit, in->seeds);
    double mean[MAX_METHODS], se[MAX_METHODS], z[MAX_METHODS];
    const char *study = in->study ? in->study : "equal-time", *names[MAX_METHODS];
    for (int i = 0; i < in->methods && i < MAX_METHODS; i++)
        names[i] = in->name[i];
    for (size_t k = 0; k < sizeof claims / sizeof *claims; k++) {
        const struct claim *cl = &claims[k];
        if (!ch6_listed(cl->studies, study)) continue;
        int mi = find(in, cl->method), others = 0;
        if (mi < 0 || isnan(in->mean[mi][cl->q])) continue; /* no reference: no image claims */
        bool have[MAX_METHODS];
        for (int i = 0; i < in->methods; i++) {
            mean[i] = in->mean[i][cl->q], se[i] = in->se[i][cl->q];
            have[i] = in->have[i] && (!cl->against || i == mi || ch6_listed(cl->against, in->name[i]));
            others += have[i] && i != mi;
        }
        if (!others) continue; /* none of those it is compared with ran */
        struct verdict v = verdict_extreme(mean, se, have, in->methods, mi, cl->sign, in->seeds, z);
        char zs[512], against[1024];
        claims_versus(names, mean, se, z, in->methods, zs, sizeof zs, against, sizeof against);
        char idbuf[64], flag[256];
        out.flag = mixing_flag(in, have, flag, sizeof flag);
        claims_row(&out, claim_id(cl, in, idbuf, sizeof idbuf), cl->source ? cl->source : in->source, cl->text,
                   cl->statistic, cl->method, mean[mi], se[mi], zs, against, &v);
        out.flag = NULL;
    }
    ratio_rows(&out, in, study);
    return claims_finish(&out, in->out, err, errlen);
}
