/* Mean luminance (image_mean.h). */
#include "common/image_mean.h"
#include "base/vecmath.h"
#include "io/image.h"

double img_mean_luminance(const struct image *im)
{
    double m = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++)
            m += luminance(img_get(im, x, y));
    return m / ((double)im->w * im->h);
}
