/* bin/render's outputs beyond the image (render_write.h): PREFIX.csv, PREFIX.angle.*, PREFIX.tech.*. */
#include "tools/render_write.h"
#include "base/dist.h"
#include "base/util.h"
#include "common/csv_meta.h"
#include "common/text_out.h"
#include "io/image.h"
#include "mc/bdpt_tech.h"
#include "mc/render.h"
#include "stats/mixing.h"
#include "stats/pixel_mixing.h"
#include "tools/mlt_cli.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The metadata lines every CSV of a run opens with: "# render SCENE --method M EXTRA", the commit
 * and the seed. */
static void meta_head(FILE *f, const struct render_args *a, const char *extra)
{
    csv_meta(f, "render", "%s --method %s%s", a->scene, a->method, extra);
    csv_meta_commit(f);
    csv_meta(f, "seed", "%llu", (unsigned long long)a->mlt.seed);
}

bool render_write_mixing(const struct render_args *a, const struct mlt_result *r, char *warn, size_t warnlen, char *err,
                         size_t errlen)
{
    struct mixing_row rows[MAX_PATH_LENGTH + 2];
    int n = mixing_rows(r->trace, r->ntrace, rows, MAX_PATH_LENGTH + 2);
    mixing_warning_line(rows, n, warn, warnlen);
    struct text_out t;
    FILE *f = text_out_open(&t);
    meta_head(f, a, "");
    csv_meta(f, "mutations", "%ld", r->mutations);
    csv_meta(f, "trace_cap", "%d", TRACE_CAP);
    mixing_write_csv(f, rows, n);
    char path[4096];
    snprintf(path, sizeof path, "%s.mixing.exr", a->out); /* visits over splats per pixel */
    bool ok = true;
    if (r->mix) {
        struct image *im = pixmix_image(r->mix);
        ok = img_write_exr(im, 1.0, path, err, errlen);
        img_destroy(im);
    }
    snprintf(path, sizeof path, "%s.mixing.csv", a->out);
    if (ok) return text_out_save(&t, path, err, errlen);
    text_out_free(&t);
    return false;
}

/* PREFIX.angle.exr (mean angle change per pixel, radians) and PREFIX.angle.csv (per length). */
bool render_write_angle(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char path[4096], extra[64];
    struct image *im = angle_acc_image(r->angle);
    snprintf(path, sizeof path, "%s.angle.exr", a->out);
    bool ok = img_write_exr(im, 1.0, path, err, errlen);
    img_destroy(im);
    struct text_out t;
    FILE *f = text_out_open(&t);
    snprintf(extra, sizeof extra, " --small-step %s", render_small_step_name(a->mlt.small_step));
    meta_head(f, a, extra);
    csv_meta(f, "skipped_steps", "%ld", r->angle->skipped);
    angle_acc_write_csv(f, r->angle);
    snprintf(path, sizeof path, "%s.angle.csv", a->out);
    if (ok) return text_out_save(&t, path, err, errlen);
    text_out_free(&t);
    return false;
}

/* The header of PREFIX.tech.csv: the run's metadata lines, then `# NAME COUNT` (mutations or spp)
 * and `# seconds`. Caller frees. */
static char *tech_head(const struct render_args *a, const char *name, long count, double seconds)
{
    char extra[64];
    struct text_out t;
    FILE *f = text_out_open(&t);
    snprintf(extra, sizeof extra, " --technique-images %d", a->mlt.technique_k);
    meta_head(f, a, extra);
    csv_meta(f, name, "%ld", count);
    csv_meta(f, "seconds", "%.3f", seconds);
    fclose(f);
    return t.buf;
}

/* The per-technique images and PREFIX.tech.csv of pssmlt and mmlt (core/stats/tech_image.h). */
bool render_write_tech(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char *head = tech_head(a, "mutations", r->mutations, r->seconds);
    bool ok = tech_acc_write(r->tech, a->out, head, err, errlen);
    free(head);
    return ok;
}

/* BDPT's (core/mc/bdpt_tech.h). */
bool render_write_bdpt_tech(const struct render_args *a, const struct render_stats *st, const struct image *img,
                            char *err, size_t errlen)
{
    char *head = tech_head(a, "spp", st->spp, st->seconds);
    bool ok = bdpt_tech_write(st->tech, st->spp, img, a->out, head, err, errlen);
    free(head);
    return ok;
}

bool render_write_mc_csv(const struct render_args *a, const struct render_stats *st, char *err, size_t errlen)
{
    struct text_out t;
    FILE *f = text_out_open(&t);
    meta_head(f, a, "");
    csv_meta(f, "threads", "%d", a->mc.threads);
    csv_meta(f, "max_length", "%d", a->mc.max_length);
    csv_meta(f, "min_length", "%d", a->mc.min_length);
    if (st->partial) csv_meta(f, NULL, "PARTIAL: interrupted after %ld samples", st->samples);
    csv_meta(f, "samples", "%ld", st->samples);
    csv_meta(f, "seconds", "%.3f", st->seconds);
    csv_meta(f, "clock", "%s", a->mc.cpu_time ? "cpu seconds per thread" : "wall");
    csv_meta(f, "samples_per_second", "%.0f", st->samples / st->seconds);
    csv_meta(f, "nonfinite", "%ld", st->nonfinite);
    fprintf(f, "method,samples,spp,seconds\n%s,%ld,%d,%.3f\n", a->method, st->samples, st->spp, st->seconds);
    char path[4096];
    snprintf(path, sizeof path, "%s.csv", a->out);
    return text_out_save(&t, path, err, errlen);
}

bool render_write_csv(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    const struct mlt_opts *m = &a->mlt;
    struct text_out t;
    FILE *f = text_out_open(&t);
    meta_head(f, a, "");
    csv_meta(f, "threads", "%d", m->threads);
    csv_meta(f, "max_length", "%d", m->max_length);
    if (dist_size() > 1) csv_meta(f, "ranks", "%d", dist_size()); /* threads are per rank */
    mlt_cli_csv(f, m, MLT_CSV_BEFORE_COUNTS);                     /* the options (core/mcmc/mlt_options.c) */
    if (m->small_step != SMALL_STEP_PSS) {
        csv_meta(f, "controlled_failed_forward", "%ld", r->ctrl_fail_forward);
        csv_meta(f, "controlled_failed_reverse", "%ld", r->ctrl_fail_reverse);
    }
    mlt_cli_csv(f, m, MLT_CSV_AFTER_COUNTS);
    if (r->partial) csv_meta(f, NULL, "PARTIAL: interrupted after %ld mutations", r->mutations);
    csv_meta(f, "mutations", "%ld", r->mutations);
    csv_meta(f, "seconds", "%.3f", r->seconds);
    csv_meta(f, "clock", "%s", m->cpu_time ? "cpu seconds per thread" : "wall");
    csv_meta(f, "seed_seconds", "%.3f", r->seed_seconds);
    csv_meta(f, "mutations_per_second", "%.0f", r->mutations / r->seconds);
    csv_meta(f, "nonfinite", "%ld", r->nonfinite);
    fputs("# nonfinite_by_length ", f); /* lengths 0..max_length; 0: sums over lengths (path/splat.h) */
    for (int k = 0; k <= m->max_length; k++)
        fprintf(f, k ? ",%ld" : "%ld", r->stats.nonfinite.len[k]);
    fputc('\n', f);
    if (m->method == MLT_PITP) {
        const struct accept_cell *pc = &r->stats.total[PROPOSAL_PITP];
        csv_meta(f, "pitp_perturbations", "%ld", pc->attempts);
        csv_meta(f, "pitp_failures", "%ld", pc->failed);
        csv_meta(f, "pitp_failure_fraction", "%.9g", pc->attempts ? (double)pc->failed / pc->attempts : 0.0);
    }
    if (m->fused != FUSED_NONE) { /* how often the chain's technique could not invert a perturbed path */
        csv_meta(f, "fused_inverted", "%ld", r->stats.fused_inverted);
        csv_meta(f, "fused_inversion_failures", "%ld", r->stats.fused_not_inverted);
    }
    /* MMLT paper §5: PSSMLT evaluates every connection of a sample, MMLT one per proposal */
    csv_meta(f, "connections_evaluated", "%ld", r->stats.conn_tried);
    csv_meta(f, "connections_nonzero", "%ld", r->stats.conn_nonzero);
    csv_meta(f, "b", "%.9g", r->b);
    csv_meta(f, "b_rse", "%.6g", r->b_rse);
    for (int k = 1; k <= m->max_length && mlt_multiplexed(m->method); k++)
        csv_meta(f, NULL, "b_%d %.9g", k, r->b_k[k]);
    for (int k = 1; k <= m->max_length && mlt_multiplexed(m->method); k++)
        csv_meta(f, NULL, "b_rse_%d %.6g", k, r->b_k_rse[k]);
    /* the large steps' own estimate of the same, and the one the image is scaled to (seed pass, or
     * under --progressive-norm both pooled) */
    long nl = 0;
    for (int k = 1; k <= m->max_length; k++)
        nl += r->large_n[k];
    csv_meta(f, "large_samples", "%ld", nl);
    csv_meta(f, "b_large", "%.9g", r->bl);
    csv_meta(f, "b_large_rse", "%.6g", r->bl_rse);
    for (int k = 1; k <= m->max_length && mlt_multiplexed(m->method); k++)
        csv_meta(f, NULL, "b_large_%d %.9g", k, r->bl_k[k]);
    for (int k = 1; k <= m->max_length && mlt_multiplexed(m->method); k++)
        csv_meta(f, NULL, "b_large_rse_%d %.6g", k, r->bl_k_rse[k]);
    csv_meta(f, "b_image", "%.9g", r->b_image);
    csv_meta(f, "b_image_rse", "%.6g", r->b_image_rse);
    stats_write_csv(f, a->method, &r->stats, true);
    char path[4096];
    snprintf(path, sizeof path, "%s.csv", a->out);
    return text_out_save(&t, path, err, errlen);
}
