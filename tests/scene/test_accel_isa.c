/* Choosing Embree's instruction set (accel.h): the names accepted, the environment override, and
 * that the choice reaches Embree (its kernels round differently). */
#include <criterion/criterion.h>
#include <stdlib.h>
#include <string.h>

#include "base/rng.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include "support/scenes.h"

static bool listed(const char *isa)
{
    for (const char *const *s = accel_isas(); *s; s++)
        if (!strcmp(*s, isa)) return true;
    return false;
}

Test(accel_isa, names_and_default)
{
    unsetenv("PSS_EMBREE_ISA");
    cr_assert(listed("sse2"), "every x86-64 CPU and Embree build runs SSE2");
    cr_assert_null(accel_isa(), "Embree's own choice by default");
    /* Embree itself would take these silently as SSE2 */
    cr_assert_not(accel_set_isa("bogus"));
    cr_assert_not(accel_set_isa("avx512skx"));
    cr_assert_null(accel_isa(), "a rejected name changes nothing");
    for (const char *const *s = accel_isas(); *s; s++) {
        cr_assert(accel_set_isa(*s), "%s", *s);
        cr_assert_str_eq(accel_isa(), *s);
    }
    cr_assert(accel_set_isa(NULL));
    cr_assert_null(accel_isa());
}

Test(accel_isa, environment_pins_the_process)
{
    setenv("PSS_EMBREE_ISA", "sse2", 1);
    cr_assert_str_eq(accel_isa(), "sse2");
    cr_assert(accel_set_isa(accel_isas()[0]));
    cr_assert(accel_set_isa(NULL));
    cr_assert_str_eq(accel_isa(), "sse2", "NULL restores the environment's choice");
    setenv("PSS_EMBREE_ISA", "avx1024", 1);
    char err[512];
    struct scene *sc = scene_load("scenes/cornell-box/scene.json", err, sizeof err);
    cr_assert_null(sc, "an ISA this machine cannot run must not fall back silently");
    cr_assert(strstr(err, "PSS_EMBREE_ISA=avx1024") && strstr(err, "sse2"), "%s", err);
}

/* 200k rays from inside scenes/materials under two kernels: hits agree to float rounding, and do
 * not all agree bit for bit when one kernel uses FMA (avx2, avx512): the ISA reached Embree. */
Test(accel_isa, kernels_round_differently)
{
    const char *const *isa = accel_isas();
    const char *lo = isa[0], *hi = NULL;
    for (; *isa; isa++)
        hi = *isa;
    struct scene *sc[2];
    cr_assert(accel_set_isa(lo));
    sc[0] = test_scene("scenes/materials/scene.json");
    cr_assert(accel_set_isa(hi));
    sc[1] = test_scene("scenes/materials/scene.json");
    accel_set_isa(NULL);
    rng r;
    rng_seed(&r, 3, 0);
    long differ = 0, n = 200000;
    for (long i = 0; i < n; i++) {
        vec3 o = v3(rng_uniform(&r) * 1.8 - 0.9, rng_uniform(&r) * 1.8 + 0.1, rng_uniform(&r) * 1.8 - 0.9);
        double z = 2 * rng_uniform(&r) - 1, phi = 2 * M_PI * rng_uniform(&r), s = sqrt(1 - z * z);
        vec3 d = v3(s * cos(phi), s * sin(phi), z);
        struct hit h[2];
        bool hit0 = accel_intersect(sc[0]->accel, o, d, 0, INFINITY, &h[0]);
        bool hit1 = accel_intersect(sc[1]->accel, o, d, 0, INFINITY, &h[1]);
        cr_assert_eq(hit0, hit1);
        if (!hit0) continue;
        cr_assert(fabs(h[0].t - h[1].t) <= 1e-5 * (1 + h[0].t), "t %.9g vs %.9g", h[0].t, h[1].t);
        differ += h[0].t != h[1].t || h[0].b1 != h[1].b1 || h[0].b2 != h[1].b2;
    }
    cr_log_info("%s vs %s: %ld of %ld hits differ in their last bits", lo, hi, differ, n);
    if (!strcmp(hi, "avx2") || !strcmp(hi, "avx512")) cr_assert(differ > 0, "%s and %s hit bit for bit alike", lo, hi);
    scene_free(sc[0]);
    scene_free(sc[1]);
}
