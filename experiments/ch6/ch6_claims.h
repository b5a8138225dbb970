/* The chapter-6 claims, each tested by several statistics at the largest budget of a bin/ch6_equal
 * run: (1) PSSMLT is worst, (2) MMLT is the splotchiest, (3) PITP is the most uniform. Writes
 * claims.csv (one row per claim and statistic: the rows of the report's claims ledger) and
 * claims.md. */
#ifndef CH6_CLAIMS_H
#define CH6_CLAIMS_H

#include <stdbool.h>
#include <stddef.h>

/* The per-run quantities of bin/ch6_equal, in the order of its summary.csv. */
enum ch6_q {
    Q_RELMSE,
    Q_SPREAD,
    Q_MPS,
    Q_NONZERO,
    Q_LARGE_NONZERO,
    Q_MUTATIONS,
    Q_BLOCK_MEDIAN,  /* median of the per-block relMSE: a firefly-robust relMSE */
    Q_TRIMMED,       /* relMSE without the 0.1 % largest pixel errors */
    Q_BLUR4,         /* share of the relative error surviving a 4 x 4 box blur */
    Q_BLUR8,         /* ... an 8 x 8 box blur */
    Q_CORRLEN,       /* correlation length of the error, pixels */
    Q_NONZERO_CONN,  /* the fraction of evaluated connections with a contribution (MMLT paper §5) */
    Q_RELMSE_SCALED, /* relMSE of the image scaled to the reference's mean: without the normalisation's part */
    Q_B_RSE,         /* the seed pass's relative standard error (the render CSV's b_rse) */
    Q_INSET_SPREAD,  /* block-relMSE spread over the blocks of the figure's two insets (--insets) */
    Q_INSET_BLUR8,   /* error share surviving an 8 x 8 blur, the mean over the two insets */
    Q_RHAT,          /* the run's largest split-R-hat (PREFIX.mixing.csv's `all` row; MCMC only) */
    Q_ESS_PER_S,     /* its effective sample size over its seconds */
    Q_STUCK,         /* its share of stuck chains */
    Q_MIX_WARN,      /* 1 when its mixing diagnostics warn (R-hat > 1.01, ESS < 100 or a stuck chain), else 0 */
    Q_NORM_ERR,      /* |image mean luminance / the reference's - 1|: the normalisation's error (and the reference's) */
    Q_B_IMAGE_RSE,   /* the relative standard error of the b the image is scaled to (seed pass or pooled) */
    Q_BLOCK_MAX,     /* log10 of the largest per-block relMSE: the error of the image's worst region */
    Q_GLOSSY_RELMSE, /* relMSE over the pixels whose first hit is glossy (glossy_mask.h) */
    Q_GLOSSY_BLUR8,  /* error share surviving an 8 x 8 blur over the 8 x 8 blocks wholly on glossy surfaces */
    Q_GLOSSY_RATIO,  /* log10 of the glossy pixels' relMSE over the other pixels': how unevenly the error falls */
    Q_COUNT
};

struct ch6_claims_in {
    const char *scene, *source, *command, *scale, *out;
    double budget;
    const char *unit; /* the budget's: "s" or "mutations per pixel" */
    int seeds, methods;
    int minlen;        /* the runs' shortest path length (1 or 2: direct light included) */
    const char *study; /* bin/ch6_equal --study (NULL: equal-time): a claim is written only in its studies */
    const char (*name)[64];
    const bool *have;
    const double (*mean)[Q_COUNT], (*se)[Q_COUNT];
};

/* Whether word is one of the space-separated list's words. */
bool ch6_listed(const char *list, const char *word);

/* Writes OUT/claims.csv and OUT/claims.md atomically and returns the Markdown (caller frees), or
 * NULL with one line in err. Claims whose method is not in the run are left out. */
char *ch6_write_claims(const struct ch6_claims_in *in, char *err, size_t errlen);

/* The MMLT paper's Fig. 5 claim (M-f) from bin/ch6_tech's follow tables of MMLT's and PSSMLT's runs
 * (columns tv and r, one row per run): MMLT's sample counts follow the per-technique contributions
 * more closely than PSSMLT's (smaller tv, larger r; z over the runs). */
struct ch6_tech_claims_in {
    const char *follow[2]; /* MMLT's, PSSMLT's */
    const char *dir, *scale, *command;
    int k;
};
/* Writes DIR/claims.csv and claims.md; returns the Markdown (caller frees), or NULL with one line in
 * err. */
char *ch6_tech_claims(const struct ch6_tech_claims_in *in, char *err, size_t errlen);

#endif
