/* The chapter-6 claims and their verdicts (ch6_claims.h). */
#include "ch6/ch6_claims.h"
#include "common/claims.h"
#include <math.h>
#include <string.h>

#define MAX_METHODS 16

static const struct claim {
    const char *id; /* results/claims-catalogue.csv */
    const char *text, *method;
    int sign; /* +1: the method's value is the largest; -1: the smallest */
    enum ch6_q q;
    const char *statistic;
    const char *against; /* the one method compared with (NULL: every other one) */
    const char *source;  /* NULL: the run's --source */
} claims[] = {
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_RELMSE, "relMSE", NULL, NULL},
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_BLOCK_MEDIAN, "median block relMSE (firefly-robust)", NULL, NULL},
    {"T32", "(1) PSSMLT is worst", "pssmlt", +1, Q_TRIMMED, "relMSE without the 0.1% largest pixel errors", NULL, NULL},
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_CORRLEN, "error correlation length (pixels)", NULL,
     NULL},
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_BLUR8, "error share surviving an 8x8 blur", NULL,
     NULL},
    {"harness:T34", "(2) MMLT is the splotchiest", "mmlt", +1, Q_SPREAD, "block-relMSE spread (CV)", NULL, NULL},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_SPREAD, "block-relMSE spread (CV)", NULL, NULL},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_BLUR8, "error share surviving an 8x8 blur", NULL,
     NULL},
    {"harness:T35", "(3) PITP is the most uniform", "pitp", -1, Q_CORRLEN, "error correlation length (pixels)", NULL,
     NULL},
    /* 11.81 % of PSSMLT's samples against 29.75 % of MMLT's on the door scene */
    {"harness:M-d", "(4) MMLT has more non-zero samples than PSSMLT", "mmlt", +1, Q_NONZERO,
     "non-zero fraction per proposal", "pssmlt", "MMLT paper §5"},
    {"harness:M-d", "(4) MMLT has more non-zero samples than PSSMLT", "mmlt", +1, Q_NONZERO_CONN,
     "non-zero fraction per connection", "pssmlt", "MMLT paper §5"},
};

static int find(const struct ch6_claims_in *in, const char *method)
{
    for (int i = 0; i < in->methods; i++)
        if (in->have[i] && !strcmp(in->name[i], method)) return i;
    return -1;
}

char *ch6_write_claims(const struct ch6_claims_in *in, char *err, size_t errlen)
{
    struct claims out;
    claims_begin(&out, in->scale, in->command, "Claims on %s at %g %s per run, %d seeds", in->scene, in->budget,
                 in->unit, in->seeds);
    double mean[MAX_METHODS], se[MAX_METHODS], z[MAX_METHODS];
    for (size_t k = 0; k < sizeof claims / sizeof *claims; k++) {
        const struct claim *cl = &claims[k];
        int mi = find(in, cl->method), oi = cl->against ? find(in, cl->against) : -1;
        if (mi < 0 || (cl->against && oi < 0) || isnan(in->mean[mi][cl->q]))
            continue; /* no reference: no image claims */
        bool have[MAX_METHODS];
        for (int i = 0; i < in->methods; i++) {
            mean[i] = in->mean[i][cl->q], se[i] = in->se[i][cl->q];
            have[i] = in->have[i] && (!cl->against || i == mi || i == oi);
        }
        struct verdict v = verdict_extreme(mean, se, have, in->methods, mi, cl->sign, in->seeds, z);
        char zs[512] = "", against[1024] = "";
        for (int i = 0; i < in->methods; i++) {
            if (isnan(z[i])) continue;
            size_t a = strlen(zs), b = strlen(against);
            snprintf(zs + a, sizeof zs - a, "%s%s=%.2f", a ? ";" : "", in->name[i], z[i]);
            snprintf(against + b, sizeof against - b, "%s%s %.4g ± %.2g (z = %.1f)", b ? "; " : "", in->name[i],
                     mean[i], se[i], z[i]);
        }
        claims_row(&out, cl->id, cl->source ? cl->source : in->source, cl->text, cl->statistic, cl->method, mean[mi],
                   se[mi], zs, against, &v);
    }
    return claims_finish(&out, in->out, err, errlen);
}
