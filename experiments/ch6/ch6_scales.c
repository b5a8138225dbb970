/* bin/ch6_equal's scales (ch6_equal.h): every setting of the make targets' quick, full and paper
 * runs, per study and scene, declared here only (ch6.mk passes --study, --scale and the scene).
 *
 * equal-time (make fig6.2 ... fig6.7): quick: budgets 0.5, 1, 2, 4 s per run, 4 seeds, a 256-spp
 * reference; full: one budget of 60 CPU seconds per thread, 8 seeds, a 4096-spp reference, 1M seed
 * paths, checkpoints each minute (an interrupted make continues), every scene at twice the quick
 * resolution; paper: 300 s from 18.75 s, 8 seeds, a 40 000-spp reference and 1M seed paths (the
 * thesis's normalisation); all: paths of length >= 3 only, as the thesis (no direct lighting), and
 * each scene's two insets (the figures' enlargements) at its resolution, with the one §6 points at
 * (the couch, the floor, the golden teapot: red, red, yellow) named for the inset statistics. ratio (make mmlt-ratio,
 * the MMLT paper's §5 setting without a reference; the target adds --min-length 2 --reference-spp 0): one budget of 4
 * s, 60 s or 300 s, 4 or 8 seeds, ajar at 256x144 (full: 512x288). hybrid (make hybrid-study, thesis §4.3 / §7.1): 3 s
 * per run (paper: 120 s), 8 seeds, 128x72, a 256-spp reference (paper: 16 384 and 1M seed paths). mmlt-equal (make
 * mmlt-equal, the MMLT paper's §5 and Fig. 4: BDPT, PSSMLT and MMLT at equal time, up to 8 bounces, direct light
 * included): one budget of 4 s, 60 s or 300 s, 4 or 8 seeds, 256x144 (full and paper: 512x288), paths of 1 to 8
 * segments, a 256-, 4096- or 16 384-spp reference; no --render-args (the target gives each method its own). mmlt-fig4
 * and mmlt-fig9 (make mmlt-fig4, mmlt-fig9: the MMLT paper's Figs. 1, 4, 6 and 9 against Veach's MLT, on ajar and on
 * ajar-diffuse) and fused-door and fused-caustic (make fused: the fused perturbations on ajar and on glass-marble) take
 * mmlt-equal's rows. cdc (make cdc-ch6, thesis §4.2): the equal-time study's budgets, seeds, lengths, references and
 * resolutions, PSSMLT with and without constrained discrete choices.
 * mis (make mis-robust, thesis Fig. 3.3): paths of 2 segments (direct light), equal samples, 16
 * (full, paper: 64) per pixel, 8 seeds (the worst block of a technique alone is heavy-tailed, and a
 * run takes a second), 128x96 (256x192), a 1024- (4096-) spp reference.
 * background (make bdpt-pt, thesis Fig. 3.4): equal samples, 16 (full, paper: 64) per pixel, 4 or 8
 * seeds, 128x72 (256x144), a 1024- (4096-) spp reference. mmlt-design (make mmlt-design, the MMLT
 * paper's §4: b_k once or progressively, one chain per length or one over all): the cdc study's
 * budgets, seeds, lengths, references and resolutions, with the equal-time study's 1M seed paths at
 * full and paper. pitp-rate (make pitp-rate, the harness's question how often PITP should move the
 * technique): cdc's rows, PITP at each rate; each method gives its own --p-large 0.1 and --pitp-rate. */
#include "base/util.h"
#include "ch6/ch6_equal.h"
#include "common/opts.h"
#include <string.h>

#define MAX_SCALE_ARGS 16
#define ALL_SCENES NULL

static const struct {
    const char *study, *scales, *scene; /* study, scales: those the row applies to, separated by spaces */
    const char *args[MAX_SCALE_ARGS];
} scales[] = {
    {"equal-time",
     "quick",
     ALL_SCENES,
     {"--time", "4", "--t0", "0.5", "--seeds", "4", "--min-length", "3", "--reference-spp", "256", "--render-args",
      "--p-large 0.1"}},
    {"equal-time", "quick paper", "living-room", {"--insets", "12,50,64,36 50,100,64,36", "--named-inset", "1"}},
    {"equal-time", "quick paper", "staircase", {"--insets", "56,0,36,64 55,130,36,64", "--named-inset", "1"}},
    {"equal-time",
     "quick paper",
     "ajar",
     {"--resolution", "256x144", "--insets", "160,70,64,36 40,60,64,36", "--named-inset", "2"}},
    {"equal-time",
     "full",
     ALL_SCENES,
     {"--time", "60", "--seeds", "8", "--min-length", "3", "--reference-spp", "4096", "--checkpoint", "60",
      "--render-args", "--p-large 0.1 --seed-paths 1000000"}},
    {"equal-time",
     "full",
     "living-room",
     {"--resolution", "512x288", "--insets", "24,100,128,72 100,200,128,72", "--named-inset", "1"}},
    {"equal-time",
     "full",
     "staircase",
     {"--resolution", "288x512", "--insets", "112,0,72,128 110,260,72,128", "--named-inset", "1"}},
    {"equal-time",
     "full",
     "ajar",
     {"--resolution", "512x288", "--insets", "320,140,128,72 80,120,128,72", "--named-inset", "2"}},
    {"equal-time",
     "paper",
     ALL_SCENES,
     {"--time", "300", "--t0", "18.75", "--seeds", "8", "--min-length", "3", "--reference-spp", "40000",
      "--render-args", "--p-large 0.1 --seed-paths 1000000"}},
    {"ratio",
     "quick",
     ALL_SCENES,
     {"--time", "4", "--seeds", "4", "--resolution", "256x144", "--render-args", "--p-large 0.1"}},
    {"ratio",
     "full",
     ALL_SCENES,
     {"--time", "60", "--seeds", "8", "--resolution", "512x288", "--checkpoint", "60", "--render-args",
      "--p-large 0.1 --seed-paths 1000000"}},
    {"ratio",
     "paper",
     ALL_SCENES,
     {"--time", "300", "--seeds", "8", "--resolution", "256x144", "--render-args",
      "--p-large 0.1 --seed-paths 1000000"}},
    {"hybrid",
     "quick full",
     ALL_SCENES,
     {"--time", "3", "--seeds", "8", "--reference-spp", "256", "--resolution", "128x72", "--render-args",
      "--p-large 0.1"}},
    {"hybrid",
     "paper",
     ALL_SCENES,
     {"--time", "120", "--seeds", "8", "--reference-spp", "16384", "--resolution", "128x72", "--render-args",
      "--p-large 0.1 --seed-paths 1000000"}},
    {"cdc mmlt-design pitp-rate",
     "quick",
     ALL_SCENES,
     {"--time", "4", "--seeds", "4", "--min-length", "3", "--reference-spp", "256", "--render-args", ""}},
    {"cdc mmlt-design pitp-rate", "quick", "ajar", {"--resolution", "256x144"}},
    {"cdc pitp-rate",
     "full paper",
     ALL_SCENES,
     {"--time", "60", "--seeds", "8", "--min-length", "3", "--reference-spp", "4096", "--checkpoint", "60",
      "--render-args", ""}},
    {"cdc mmlt-design pitp-rate", "full paper", "living-room", {"--resolution", "512x288"}},
    {"cdc mmlt-design pitp-rate", "full paper", "staircase", {"--resolution", "288x512"}},
    {"cdc mmlt-design pitp-rate", "full paper", "ajar", {"--resolution", "512x288"}},
    {"mis",
     "quick",
     ALL_SCENES,
     {"--spp", "16", "--seeds", "8", "--resolution", "128x96", "--min-length", "2", "--max-length", "2",
      "--reference-spp", "1024", "--render-args", ""}},
    {"mis",
     "full paper",
     ALL_SCENES,
     {"--spp", "64", "--seeds", "8", "--resolution", "256x192", "--min-length", "2", "--max-length", "2",
      "--reference-spp", "4096", "--render-args", ""}},
    {"background",
     "quick",
     ALL_SCENES,
     {"--spp", "16", "--seeds", "4", "--resolution", "128x72", "--reference-spp", "1024", "--render-args", ""}},
    {"background",
     "full paper",
     ALL_SCENES,
     {"--spp", "64", "--seeds", "8", "--resolution", "256x144", "--reference-spp", "4096", "--render-args", ""}},
    {"mmlt-equal mmlt-fig4 mmlt-fig9 fused-door fused-caustic",
     "quick",
     ALL_SCENES,
     {"--time", "4", "--seeds", "4", "--resolution", "256x144", "--min-length", "1", "--max-length", "8",
      "--reference-spp", "256", "--render-args", ""}},
    {"mmlt-equal mmlt-fig4 mmlt-fig9 fused-door fused-caustic",
     "full",
     ALL_SCENES,
     {"--time", "60", "--seeds", "8", "--resolution", "512x288", "--min-length", "1", "--max-length", "8",
      "--reference-spp", "4096", "--checkpoint", "60", "--render-args", ""}},
    {"mmlt-equal mmlt-fig4 mmlt-fig9 fused-door fused-caustic",
     "paper",
     ALL_SCENES,
     {"--time", "300", "--seeds", "8", "--resolution", "512x288", "--min-length", "1", "--max-length", "8",
      "--reference-spp", "16384", "--checkpoint", "60", "--render-args", ""}},
    {"mmlt-design",
     "full paper",
     ALL_SCENES,
     {"--time", "60", "--seeds", "8", "--min-length", "3", "--reference-spp", "4096", "--checkpoint", "60",
      "--render-args", "--seed-paths 1000000"}},
};

/* The scene's folder name: "scenes/ajar/scene.json" -> "ajar". */
static bool scene_is(const char *path, const char *name)
{
    const char *end = strrchr(path, '/'), *start = end;
    if (!end) return false;
    while (start > path && start[-1] != '/')
        start--;
    return (size_t)(end - start) == strlen(name) && !strncmp(start, name, (size_t)(end - start));
}

char **ch6_with_scale(const struct opts_spec *spec, int *argc, char **argv)
{
    const char *scale = NULL, *study = "equal-time", *scene = "";
    for (int i = 1; i < *argc; i++) {
        const struct opt *o = opts_find(spec, argv[i]);
        if (!o || o->type == OPT_FLAG) continue;
        if (i + 1 < *argc && !strcmp(o->name, "--scale")) scale = argv[i + 1];
        if (i + 1 < *argc && !strcmp(o->name, "--study")) study = argv[i + 1];
        if (i + 1 < *argc && !strcmp(o->name, "--scene")) scene = argv[i + 1];
        i++;
    }
    if (!scale) return argv;
    const char *add[4 * MAX_SCALE_ARGS];
    int n = 0;
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        if (!ch6_listed(scales[k].study, study) || !ch6_listed(scales[k].scales, scale) ||
            (scales[k].scene && !scene_is(scene, scales[k].scene)))
            continue;
        for (int j = 0; j < MAX_SCALE_ARGS && scales[k].args[j] && n < 4 * MAX_SCALE_ARGS; j++)
            add[n++] = scales[k].args[j];
    }
    if (!n) return argv;
    char **v = xmalloc(sizeof(char *) * (size_t)(*argc + n + 1));
    v[0] = argv[0];
    memcpy(v + 1, add, sizeof(char *) * (size_t)n);
    memcpy(v + 1 + n, argv + 1, sizeof(char *) * (size_t)*argc); /* argv[1..argc], NULL included */
    *argc += n;
    return v;
}
