/* The options every acceptance figure tool shares (fig4_5, fig6_1): see cli.h. */
#include "base/parallel.h"
#include "common/cli.h"
#include "path/scene_ready.h"
#include "sampler/sampler.h"
#include "scene/scene.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void cli_figure_parse(const char *prog, const char *usage, int argc, char **argv, struct cli_figure *f)
{
    const char *env = getenv("SCALE");
    f->scale = env && *env ? env : "quick";
    f->mutations = -1;
    f->max_length = 12;
    f->threads = cpu_count();
    f->seed = 1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            fputs(usage, stdout);
            exit(0);
        } else if (!strcmp(o, "--scene")) f->scene = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--scale")) f->scale = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--mutations")) f->mutations = cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1L << 40);
        else if (!strcmp(o, "--max-length")) f->max_length = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, MAX_PATH_LENGTH);
        else if (!strcmp(o, "--seed")) f->seed = cli_u64(prog, o, cli_value(prog, argc, argv, &i));
        else if (!strcmp(o, "--threads")) f->threads = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1024);
        else if (!strcmp(o, "--out")) f->out = cli_value(prog, argc, argv, &i);
        else cli_fail(prog, "unknown option '%s' (see --help)", o);
    }
    f->paper = !strcmp(f->scale, "paper");
    if (!f->paper && strcmp(f->scale, "quick")) cli_fail(prog, "--scale: expected quick or paper, got '%s'", f->scale);
}

struct scene *cli_figure_scene(const struct cli_figure *f)
{
    char err[1024];
    struct scene *sc = scene_load(f->scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        exit(2);
    }
    mkdir(f->out, 0777);
    return sc;
}
