/* The independence sampler's acceptance from its proposal's draws (see indep_accept.h). */
#include "stats/indep_accept.h"
#include "base/util.h"
#include <math.h>
#include <stdlib.h>

struct draw {
    double w;
    long cluster;
};

/* by weight, ties by cluster, so that the sums below do not depend on the order of the input */
static int by_weight(const void *a, const void *b)
{
    const struct draw *x = a, *y = b;
    if (x->w != y->w) return (x->w > y->w) - (x->w < y->w);
    return (x->cluster > y->cluster) - (x->cluster < y->cluster);
}

static int by_cluster(const void *a, const void *b)
{
    const struct draw *x = a, *y = b;
    if (x->cluster != y->cluster) return (x->cluster > y->cluster) - (x->cluster < y->cluster);
    return by_weight(a, b);
}

static long clusters_in(long clusters, int groups, int g) { return clusters / groups + (g < clusters % groups); }

void indep_accept(const struct weighted_draws *d, double *theta)
{
    int G = d->groups;
    double within[JACK_MAX_GROUPS] = {0}, sumw[JACK_MAX_GROUPS] = {0}, smin[JACK_MAX_GROUPS + 1] = {0};
    struct draw *s = xmalloc((size_t)(d->n > 0 ? d->n : 1) * sizeof *s);
    for (long i = 0; i < d->n; i++)
        s[i] = (struct draw){d->w[i], d->cluster[i]};
    /* pairs inside one cluster: left out of every sum below */
    qsort(s, (size_t)d->n, sizeof *s, by_cluster);
    for (long i = 0; i < d->n;) {
        long e = i;
        while (e < d->n && s[e].cluster == s[i].cluster)
            e++;
        for (long a = i; a < e; a++)
            for (long b = a + 1; b < e; b++)
                within[s[i].cluster % G] += fmin(s[a].w, s[b].w);
        i = e;
    }
    qsort(s, (size_t)d->n, sizeof *s, by_weight);
    for (long i = 0; i < d->n; i++)
        sumw[s[i].cluster % G] += s[i].w;
    /* sum over pairs of min(w_i, w_j): ascending order, each weight times the draws above it;
     * replicate g (index g + 1) counts only draws outside group g, 0 all of them */
    long above[JACK_MAX_GROUPS + 1] = {0};
    for (long i = d->n - 1; i >= 0; i--) {
        int gi = (int)(s[i].cluster % G);
        for (int g = 0; g <= G; g++) {
            if (g == gi + 1) continue;
            smin[g] += s[i].w * (double)above[g];
            above[g]++;
        }
    }
    free(s);
    double tw = 0, tin = 0;
    for (int g = 0; g < G; g++)
        tw += sumw[g], tin += within[g];
    for (int g = 0; g <= G; g++) {
        long c = g == 0 ? d->clusters : d->clusters - clusters_in(d->clusters, G, g - 1);
        double m = (double)c * d->per_cluster;
        double pairs = m * (m - 1) / 2 - (double)c * d->per_cluster * (d->per_cluster - 1) / 2;
        double w = g == 0 ? tw : tw - sumw[g - 1], in = g == 0 ? tin : tin - within[g - 1];
        theta[g] = w > 0 && pairs > 0 ? ((smin[g] - in) / pairs) / (w / m) : NAN;
    }
}

void jack_mean(const double *v, long clusters, int groups, double *theta)
{
    double sum[JACK_MAX_GROUPS] = {0}, t = 0;
    for (long c = 0; c < clusters; c++)
        sum[c % groups] += v[c];
    for (int g = 0; g < groups; g++)
        t += sum[g];
    theta[0] = t / (double)clusters;
    for (int g = 0; g < groups; g++)
        theta[g + 1] = (t - sum[g]) / (double)(clusters - clusters_in(clusters, groups, g));
}

double jack_se(const double *theta, int groups)
{
    double m = 0, v = 0;
    for (int g = 1; g <= groups; g++)
        m += theta[g] / groups;
    for (int g = 1; g <= groups; g++)
        v += (theta[g] - m) * (theta[g] - m);
    return sqrt(v * (groups - 1) / groups);
}
