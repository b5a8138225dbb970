/* bin/render's outputs beside PREFIX.exr and PREFIX.png (render_write.c), each written atomically
 * and opening with the run's metadata lines (common/csv_meta.h). */
#ifndef RENDER_WRITE_H
#define RENDER_WRITE_H

#include "tools/render_args.h"
#include <stdbool.h>
#include <stddef.h>

struct image;
struct render_stats;

/* PREFIX.csv: the MCMC run's options, counts, normalisation and per-length acceptance. */
bool render_write_csv(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen);
/* PREFIX.csv of pt and bdpt: the run's samples and time (metadata) and one row, so that a
 * comparison at equal time (bin/ch6_equal) reads every method's run the same way. */
bool render_write_mc_csv(const struct render_args *a, const struct render_stats *st, char *err, size_t errlen);
/* PREFIX.mixing.csv: the chains' mixing diagnostics per length and over all (core/stats/mixing.h), and
 * PREFIX.mixing.exr, distinct states over splats per pixel (core/stats/pixel_mixing.h);
 * into warn (when a row warns; else "") the summary's warning. */
bool render_write_mixing(const struct render_args *a, const struct mlt_result *r, char *warn, size_t warnlen, char *err,
                         size_t errlen);
/* PREFIX.angle.exr (mean angle change per pixel, radians) and PREFIX.angle.csv (per length). */
bool render_write_angle(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen);
/* The per-technique images and PREFIX.tech.csv of pssmlt and mmlt (core/stats/tech_image.h). */
bool render_write_tech(const struct render_args *a, const struct mlt_result *r, char *err, size_t errlen);
/* BDPT's (core/mc/bdpt_tech.h). */
bool render_write_bdpt_tech(const struct render_args *a, const struct render_stats *st, const struct image *img,
                            char *err, size_t errlen);

#endif
