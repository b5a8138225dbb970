#include "support/isa.h"
#include "scene/accel.h"
#include <criterion/criterion.h>
#include <stdlib.h>

void test_each_isa(void (*fn)(const char *isa, void *ctx), void *ctx)
{
    const char *env = getenv("PSS_EMBREE_ISA");
    if (env && *env) {
        cr_assert(accel_set_isa(env), "PSS_EMBREE_ISA=%s: not an instruction set this CPU and Embree run", env);
        fn(env, ctx);
        accel_set_isa(NULL);
        return;
    }
    const char *const *isa = accel_isas();
    cr_assert(isa[0], "no Embree instruction set runs on this machine");
    for (; *isa; isa++) {
        cr_assert(accel_set_isa(*isa));
        fn(*isa, ctx);
    }
    accel_set_isa(NULL);
}
