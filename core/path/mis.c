/* Balance-heuristic weights of every technique of a path from the density ratios
 * p_{j+1} / p_j = pl(x_j) / pc(x_j) (thesis Eq. 5.21-5.25, Veach §10.2). A Dirac density (0) counts
 * as 1: it appears in every technique that samples through the delta vertex and cancels. Across a
 * chain of delta vertices the densities are those of the unfolded path (mis_unfold_delta_chains,
 * path.h): only then do the Dirac factors cancel between the techniques on either side. */
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
    for (int j = 0; j <= k; j++)
        ratios[j] = 0;
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

double mis_power_weight(const double *ratios, int k)
{
    double sum = 0;
    for (int j = 0; j <= k; j++)
        sum += ratios[j] * ratios[j];
    return 1.0 / sum;
}

/* Unit direction and length of the segment x_i -> x_{i+1}; the length is 0 when x_i lies at
 * infinity (only x_0 can: an environment vertex). */
static vec3 seg(const struct vertex *const *x, int i, double *len)
{
    double d2;
    vec3 d = edge_dir(x[i], x[i + 1], &d2);
    *len = x[i]->kind == VK_ENV ? 0 : sqrt(d2);
    return d;
}

/* The cosine edge_pdf converts with at vertex v reached along d. */
static double cos_at(const struct vertex *v, vec3 d) { return v->kind == VK_CAMERA ? 1.0 : fabs(vdot(v->ng, d)); }

/* The chain x_{a+1} .. x_{b-1} of delta vertices between the non-delta x_a and x_b. */
static void unfold_chain(struct mis_path *m, const struct vertex *const *x, int a, int b)
{
    bool from_env = x[a]->kind == VK_ENV;
    double len_first, len_last = 0, L = 0;
    vec3 first = seg(x, a, &len_first), last = first;
    L = len_last = len_first;
    for (int i = a + 1; i < b; i++) {
        last = seg(x, i, &len_last);
        L += len_last;
    }
    double c_first = cos_at(x[a + 1], first), c_last = cos_at(x[b - 1], last);
    if (!(c_first > 0 && c_last > 0 && (from_env || L > 0))) return; /* degenerate: left as it was */
    /* The chain's first vertex from either end, back in solid angle (edge_pdf undone). */
    m->pl[a + 1] *= (from_env ? 1.0 : sqr(len_first)) / c_first;
    m->pc[b - 1] *= sqr(len_last) / c_last;
    /* The far ends over the unfolded chain; a beam from infinity is parallel: no falloff. */
    double fall = from_env ? 1.0 : 1.0 / sqr(L);
    m->pl[b] = cos_at(x[b], last) * fall;
    m->pc[a] = from_env ? 1.0 : cos_at(x[a], first) * fall;
}

void mis_unfold_delta_chains(struct mis_path *m, const struct vertex *const *x)
{
    for (int a = 0; a + 1 < m->k; a++) {
        if (m->delta[a] || !m->delta[a + 1]) continue;
        int b = a + 2;
        while (b <= m->k && m->delta[b])
            b++;
        if (b > m->k) return;
        unfold_chain(m, x, a, b);
        a = b - 1;
    }
}
