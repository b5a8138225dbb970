/* Splatting a contribution at a continuous raster position (image.h): the box puts all of it in the
 * pixel containing the position; the tent of radius 1 spreads it over the 2x2 nearest pixel
 * centres with weights (1 - |dx|)(1 - |dy|), which sum to 1 inside the image, and drops what falls
 * on pixels outside it. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "io/image.h"

static double total(const struct image *im)
{
    double s = 0;
    for (int i = 0; i < im->w * im->h; i++)
        s += im->px[3 * i];
    return s;
}

static void clear(struct image *im)
{
    for (int i = 0; i < im->w * im->h * 3; i++)
        im->px[i] = 0;
}

Test(image_splat, box_fills_the_containing_pixel)
{
    struct image *im = img_create(8, 6);
    img_splat(im, 3.7, 2.2, v3(1, 2, 3));
    cr_assert(img_get(im, 3, 2).x == 1 && img_get(im, 3, 2).z == 3 && total(im) == 1);
    img_splat(im, -0.2, 2.2, v3s(1));
    img_splat(im, 8.0, 2.2, v3s(1));
    img_splat(im, 3.0, 6.0, v3s(1));
    cr_assert(total(im) == 1, "a position outside the image was splatted");
    img_destroy(im);
}

Test(image_splat, tent_weights)
{
    struct image *im = img_create(8, 6);
    im->tent = true;
    img_splat(im, 3.5, 2.5, v3s(1)); /* a pixel centre */
    cr_assert(img_get(im, 3, 2).x == 1 && total(im) == 1);
    clear(im);
    img_splat(im, 3.0, 2.5, v3s(1)); /* halfway between two centres */
    cr_assert(img_get(im, 2, 2).x == 0.5 && img_get(im, 3, 2).x == 0.5);
    clear(im);
    img_splat(im, 3.75, 2.25, v3s(1));
    cr_assert(fabs(img_get(im, 3, 2).x - 0.75 * 0.75) < 1e-15 && fabs(img_get(im, 4, 1).x - 0.25 * 0.25) < 1e-15);
    cr_assert(fabs(img_get(im, 4, 2).x - 0.25 * 0.75) < 1e-15 && fabs(img_get(im, 3, 1).x - 0.75 * 0.25) < 1e-15);
    clear(im);
    img_splat(im, -0.5, 2.5, v3s(1)); /* one pixel from pixel 0's centre: weight 0 */
    img_splat(im, 8.5, 2.5, v3s(1));
    cr_assert(total(im) == 0);
    img_destroy(im);
}

/* 100k random positions over the film [-1, w + 1) x [-1, h + 1): what lands equals the product of
 * the in-image tent weights on each axis, which is 1 for positions at least half a pixel inside. */
Test(image_splat, tent_partition_of_unity)
{
    struct image *im = img_create(7, 5);
    im->tent = true;
    rng r;
    rng_seed(&r, 5, 0);
    for (int i = 0; i < 100000; i++) {
        double px = -1 + 9 * rng_uniform(&r), py = -1 + 7 * rng_uniform(&r);
        clear(im);
        img_splat(im, px, py, v3s(1));
        double ex = 1, ey = 1;
        if (px < 0.5) ex = px > -0.5 ? 1 - (0.5 - px) : 0;
        if (px > 6.5) ex = px < 7.5 ? 1 - (px - 6.5) : 0;
        if (py < 0.5) ey = py > -0.5 ? 1 - (0.5 - py) : 0;
        if (py > 4.5) ey = py < 5.5 ? 1 - (py - 4.5) : 0;
        cr_assert(fabs(total(im) - ex * ey) < 1e-12, "(%g, %g): %g landed, expected %g", px, py, total(im), ex * ey);
    }
    img_destroy(im);
}
