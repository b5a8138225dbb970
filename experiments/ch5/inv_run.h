/* One sampling function's test (thesis Eq. 5.3): n forward samples from fresh numbers (the
 * reference: the numbers of successful forward samples), then n more forward samples, each
 * inverted; the inverted numbers are tested against the uniform density when no forward sample
 * failed in either pass (then the forward numbers of produced samples are uniform), otherwise
 * against the reference (two-sample tests). Inversion failures are counted, not tested. */
#ifndef INV_RUN_H
#define INV_RUN_H

#include "ch5/inv_funcs.h"

struct inv_result {
    long samples;   /* forward samples inverted successfully: the tested numbers */
    long failures;  /* forward samples the inverse refused (or mapped outside [0, 1)) */
    long fwd_tries; /* forward draws of both passes */
    long fwd_fails; /* of them, draws that produced no sample */
    bool uniform;   /* tested against the uniform density (else against the reference) */
    struct inv_gof g;
};

/* Seeds come from (seed, the function's name): a function's numbers do not depend on the others.
 * `scale_first` (1: none): the first inverted number of every sample is multiplied by it, a broken
 * inverse the test must reject (the check's and the unit test's demonstration). Forward draws stop at 100 n per pass
 * (a function whose samples are rarer tests fewer). */
void inv_run(const struct inv_func *f, struct inv_scratch *x, long n, uint64_t seed, double scale_first,
             struct inv_result *r);

#endif
