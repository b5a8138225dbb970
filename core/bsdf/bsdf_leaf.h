/* Shared pieces of the leaf BSDF families of Tungsten (thinsheet, diffuse_transmission,
 * oren_nayar, phong): lobe indices reported in bsdf_sample.lobe and the thin sheet's optics, which
 * the tests recompute.
 *
 * Lobe indices and numbers consumed (discrete first, its intervals in lobe order from 0):
 *   thinsheet             0 reflection, 1 straight transmission      1 (discrete)
 *   diffuse_transmission  0 reflection, 1 transmission               3 (1 discrete, 2 continuous)
 *   oren_nayar            0 uniform hemisphere, 1 cosine hemisphere   3 (1 discrete, 2 continuous)
 *   phong                 0 glossy lobe, 1 diffuse lobe               3 (1 discrete, 2 continuous) */
#ifndef BSDF_LEAF_H
#define BSDF_LEAF_H

#include "base/vecmath.h"
#include "scene/scene.h"

enum { THINSHEET_LOBE_REFLECT = 0, THINSHEET_LOBE_TRANSMIT = 1 };
enum { DIFFTRANS_LOBE_REFLECT = 0, DIFFTRANS_LOBE_TRANSMIT = 1 };
enum { OREN_NAYAR_LOBE_UNIFORM = 0, OREN_NAYAR_LOBE_COSINE = 1 };
enum { PHONG_LOBE_GLOSSY = 0, PHONG_LOBE_DIFFUSE = 1 };

/* A thin sheet seen at |cos theta_i| = cos_i: R, the (grey) reflectance of its two interfaces with
 * every inter-reflection summed; T, what goes straight through after absorption over the path
 * 2 thickness / cos theta_t inside (Tungsten's ThinSheetBsdf, interference off). */
struct thinsheet_optics {
    double R;
    rgb T;
};
struct thinsheet_optics thinsheet_optics(const struct bsdf *b, double cos_i);

#endif
