/* The geometry scan behind the toy's free constants (../README.md): RMSE of PSS-MLT-1 and
 * PSS-MLT-2 alone at one budget against a reference, over seeds, for one compiled variant of the
 * toy. usage: scan N_MILLIONS SEEDS REF_SPP. Seeds 1000003 + s, stream = algorithm index (not
 * table1_cmlt's seeds, so that the runs that test the orderings are independent of the choice).
 * Prints both means with their standard errors and the ratio with its delta-method error. */
#include "base/util.h"
#include "cmlt/cmlt_mcmc.h"
#include "cmlt/cmlt_reference.h"
#include "common/die.h"
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#define W 128
#define MAX_JOBS 64

struct job {
    int algo, seed;
    double rmse;
};

static uint64_t n_steps;
static double *ref;
static struct job jobs[MAX_JOBS];
static int next_job, njobs;
static pthread_mutex_t mu = PTHREAD_MUTEX_INITIALIZER;

static void *work(void *arg)
{
    (void)arg;
    double *img = xmalloc(sizeof(double) * 3 * W * W);
    for (;;) {
        pthread_mutex_lock(&mu);
        int k = next_job++;
        pthread_mutex_unlock(&mu);
        if (k >= njobs) break;
        struct cmlt_config c;
        cmlt_config_default(&c);
        c.w = c.h = W;
        c.n = n_steps;
        c.n_seed = n_steps / 16;
        struct cmlt_stats st;
        cmlt_run((enum cmlt_algo)jobs[k].algo, &c, 1000003ull + (uint64_t)jobs[k].seed, (uint64_t)jobs[k].algo, img,
                 &st, NULL, NULL);
        double s = 0;
        for (int i = 0; i < 3 * W * W; i++)
            s += (img[i] - ref[i]) * (img[i] - ref[i]);
        jobs[k].rmse = sqrt(s / (3.0 * W * W));
    }
    free(img);
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc != 4) die(DIE_USAGE, "scan", "usage: scan N_MILLIONS SEEDS REF_SPP");
    n_steps = (uint64_t)(atof(argv[1]) * 1e6);
    int seeds = atoi(argv[2]), spp = atoi(argv[3]);
    if (n_steps < 1024 || seeds < 2 || 2 * seeds > MAX_JOBS || spp < 1) die(DIE_USAGE, "scan", "bad arguments");
    ref = xmalloc(sizeof(double) * 3 * W * W);
    struct cmlt_ref_result rr;
    cmlt_reference(W, W, spp, 0xC3117ull, 2, ref, &rr, NULL);
    for (int s = 0; s < seeds; s++)
        for (int a = 0; a < 2; a++)
            jobs[njobs++] = (struct job){a, s, 0};
    pthread_t t[2];
    for (int i = 0; i < 2; i++)
        pthread_create(&t[i], NULL, work, NULL);
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    double m[2] = {0}, v[2] = {0}; /* v: squared standard error of the mean */
    for (int k = 0; k < njobs; k++)
        m[jobs[k].algo] += jobs[k].rmse / seeds;
    for (int k = 0; k < njobs; k++)
        v[jobs[k].algo] += pow(jobs[k].rmse - m[jobs[k].algo], 2) / (seeds - 1) / seeds;
    double r = m[0] / m[1], rse = r * sqrt(v[0] / m[0] / m[0] + v[1] / m[1] / m[1]);
    printf("pss1 %.4e +- %.1e  pss2 %.4e +- %.1e  ratio %.3f +- %.3f  refnoise %.2e b %.4g\n", m[0], sqrt(v[0]), m[1],
           sqrt(v[1]), r, rse, rr.noise_rmse, rr.b[0]);
    free(ref);
    return 0;
}
