/* Decoded channels → RGB texels; see texels.h. */
#include "io/texels.h"
#include "base/util.h"

float *texels_to_rgb(int w, int h, int nc, const float *chan)
{
    size_t n = (size_t)w * (size_t)h;
    float *rgb = xmalloc(n * 3 * sizeof(float));
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = chan[i * (size_t)nc + (nc >= 3 ? c : 0)];
    return rgb;
}
