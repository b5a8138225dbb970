/* The test-only injection of non-finite contributions (splat.h). */
#include "path/splat.h"

long nonfinite_inject_every;

rgb nonfinite_injected(rgb v)
{
    static _Thread_local long n; /* per thread: a run of fixed threads injects at fixed samples */
    if (vzero(v) || ++n % nonfinite_inject_every) return v;
    return n / nonfinite_inject_every % 2 ? v3(NAN, v.y, v.z) : v3(v.x, INFINITY, v.z);
}
