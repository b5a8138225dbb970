/* Weighted discrete picks (see pick.h). */
#include "sampling/pick.h"

int pick_weighted(const double *w, int n, double u)
{
    double sum = 0, acc = 0;
    for (int i = 0; i < n; i++)
        sum += w[i];
    u *= sum;
    int j = 0;
    for (; j < n - 1; j++)
        if ((acc += w[j]) > u && w[j] > 0) break;
    while (j > 0 && w[j] == 0)
        j--; /* rounding at the top end */
    return j;
}

long pick_cdf(const double *cdf, long n, double u)
{
    long lo = 0, hi = n - 1;
    double x = u * cdf[n - 1];
    while (lo < hi) {
        long mid = (lo + hi) / 2;
        if (cdf[mid] > x)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}
