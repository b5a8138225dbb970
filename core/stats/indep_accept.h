/* The mean acceptance of an independence Metropolis-Hastings chain, predicted from independent
 * draws of its proposal. A chain whose proposal y ~ q ignores the state, with target w q (x ~ w q
 * at stationarity), accepts with E[min(1, w(y) / w(x))] = E[min(W1, W2)] / E[W] for W1, W2
 * independent draws of w under q (as w(x) min(1, w(y) / w(x)) = min(w(x), w(y))). Every large
 * step of MMLT and MCTLS is such a proposal (thesis §4.3), so the acceptance curves of Fig. 4.5
 * follow from the distribution of the trials' targets alone: which makes the prediction a check of
 * the chains, and lets the weight be swapped for another to see what sets the curves.
 *
 * Draws come in clusters (for MMLT's large step, the k + 1 techniques of one pair of subpaths):
 * every cluster has the same number of draws, the positive ones listed with their cluster; pairs of
 * draws within one cluster are left out, as they are not independent. Clusters are dealt to G
 * groups; the estimate is returned with its G delete-a-group jackknife replicates, from which
 * jack_se() gives the standard error of it and of any smooth function of several such estimates
 * (apply the function to the replicates elementwise). */
#ifndef INDEP_ACCEPT_H
#define INDEP_ACCEPT_H

/* The most jackknife groups. */
#define JACK_MAX_GROUPS 64

struct weighted_draws {
    long n;          /* positive draws */
    double *w;       /* their weights */
    long *cluster;   /* and clusters, 0..clusters-1 (cluster c is in group c % groups) */
    long clusters;   /* all clusters, with or without a positive draw */
    int per_cluster; /* draws per cluster, zeros included */
    int groups;      /* 2..JACK_MAX_GROUPS */
};

/* theta[0]: E[min(W1, W2)] / E[W] over all draws; theta[1..groups]: the same without group g.
 * NAN where E[W] is 0. The draws may come in any order. */
void indep_accept(const struct weighted_draws *d, double *theta);
/* A mean over clusters of a per-cluster value v[c] (zero-cluster values count), with its replicates. */
void jack_mean(const double *v, long clusters, int groups, double *theta);
/* The jackknife standard error from theta[0..groups]. */
double jack_se(const double *theta, int groups);

#endif
