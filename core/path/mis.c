/* Balance-heuristic weights of every technique of a path from the density ratios
 * p_{j+1} / p_j = pl(x_j) / pc(x_j) (thesis Eq. 5.21-5.25, Veach §10.2). A Dirac density (0) counts
 * as 1: it appears in every technique that samples through the delta vertex and cancels. */
#include "path/path.h"

static double remap0(double x) { return x != 0 ? x : 1.0; }

/* Technique j joins x_{j-1} and x_j by a deterministic connection: impossible at a delta vertex. */
static bool connectable(const struct mis_path *m, int j)
{
    if (j > 0 && m->delta[j - 1]) return false;
    return !m->delta[j];
}

double mis_weights(const struct mis_path *m, int s, int max_s, double *ratios)
{
    int k = m->k;
    for (int j = 0; j <= k; j++) ratios[j] = 0;
    ratios[s] = 1;
    double sum = 1, r = 1;
    for (int j = s; j < k && j < max_s; j++) { /* more emitter vertices */
        r *= remap0(m->pl[j]) / remap0(m->pc[j]);
        if (connectable(m, j + 1)) {
            ratios[j + 1] = r;
            sum += r;
        }
    }
    r = 1;
    for (int j = s - 1; j >= 0; j--) { /* more camera vertices */
        r *= remap0(m->pc[j]) / remap0(m->pl[j]);
        if (connectable(m, j)) {
            ratios[j] = r;
            sum += r;
        }
    }
    return 1.0 / sum;
}

double mis_max_weight(const double *ratios, int k, int s)
{
    for (int j = 0; j <= k; j++)
        if (ratios[j] > 1 || (ratios[j] == 1 && j < s)) return 0;
    return 1;
}
