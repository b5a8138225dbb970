/* bin/table1_cmlt's parts (CMLT paper Table 1 and Figure 3; table1_cmlt.c holds its options and
 * main): the cached reference and the pool of chains over every (seed, budget, algorithm)
 * (table1_runs.c), and the tables, Markdown and images written from them (table1_write.c). */
#ifndef TABLE1_H
#define TABLE1_H

#include "base/parallel.h"
#include "cmlt/cmlt_claims.h"
#include "cmlt/cmlt_mcmc.h"
#include "cmlt/cmlt_reference.h"
#include "common/text_out.h"
#include "io/image.h"
#include <signal.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#define TABLE1_MAX_BUDGETS CMLT_MAX_BUDGETS
#define TABLE1_MAX_SEEDS 1000

struct table1_opts {
    const char *scale, *out, *commit;
    uint64_t budgets[TABLE1_MAX_BUDGETS];
    int nbudgets, seeds, threads, res, ref_spp, swap_every, bench;
    uint64_t seed;
    double p_large, seed_frac;
};

/* One chain: an algorithm at budget n (index bidx) with seed seed_idx, and what it measured. */
struct table1_job {
    int algo, bidx, seed_idx;
    uint64_t n;
    double rmse;
    struct cmlt_stats st;
};

/* The jobs of a run and the threads' shared counters. */
struct table1_pool {
    const struct table1_opts *o;
    const struct image *ref;
    struct table1_job *jobs;
    int njobs;
    _Atomic int next;
    struct progress progress;
    const volatile sig_atomic_t *stop; /* set by the caller's SIGINT handler: chains end early */
    double **keep;                     /* [bidx * CMLT_NALGO + algo]: image of seed 0 */
};

/* What the run's tables share: the RMSE mean and standard error per (budget, algorithm), and those
 * of each seed's acceptance and steps per second (the claims'). */
struct table1_summary {
    double mean[TABLE1_MAX_BUDGETS][CMLT_NALGO], se[TABLE1_MAX_BUDGETS][CMLT_NALGO];
    double acc[2][TABLE1_MAX_BUDGETS][CMLT_NALGO], rate[2][TABLE1_MAX_BUDGETS][CMLT_NALGO];
    double wall;
    int partial;
};

/* table1_write.c, for both: the error line of a failed write ("table1_cmlt: ...", exit status 1),
 * and n as the tables and file names write it (16M, 1024k, 1500). */
void table1_save_or_die(bool ok, const char *err);
const char *table1_fmt_n(uint64_t n, char *buf, size_t len);

/* table1_runs.c: the reference, loaded from OUT/reference.exr when OUT/reference.key names this
 * resolution, sample count and toy, else computed (a progress bar on stderr) and cached. */
struct image *table1_reference(const struct table1_opts *o, struct cmlt_ref_result *res);
/* The jobs of every (seed, budget, algorithm), largest budgets first, and room for the first seed's
 * images; run on o->threads threads (a progress bar on stderr), each job's RMSE against p->ref. */
void table1_pool_make(struct table1_pool *p);
void table1_pool_run(struct table1_pool *p, const char *what);
void table1_pool_free(struct table1_pool *p);

/* table1_write.c: table1.csv, table1_stats.csv, table1_seeds.csv and table1.md (md: its text
 * stays in md->buf until text_out_free; a failed write is the error line and exit status 1), and
 * sm's means and standard errors for the claims. */
void table1_write_tables(const struct table1_pool *p, struct table1_summary *sm, double noise_rmse,
                         struct text_out *md);
/* <algo>_<n>.exr and .png of the first seed. */
bool table1_write_images(const struct table1_pool *p, char *err, size_t errlen);

#endif
