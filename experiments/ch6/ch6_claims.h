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
    Q_COUNT
};

struct ch6_claims_in {
    const char *scene, *source, *command, *scale, *out;
    double budget;
    const char *unit; /* the budget's: "s" or "mutations per pixel" */
    int seeds, methods;
    const char (*name)[64];
    const bool *have;
    const double (*mean)[Q_COUNT], (*se)[Q_COUNT];
};

/* Writes OUT/claims.csv and OUT/claims.md atomically and returns the Markdown (caller frees), or
 * NULL with one line in err. Claims whose method is not in the run are left out. */
char *ch6_write_claims(const struct ch6_claims_in *in, char *err, size_t errlen);

#endif
