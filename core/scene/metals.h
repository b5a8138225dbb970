/* Named conductors: RGB complex index of refraction (eta + i k), the values Tungsten uses
 * (src/core/bsdfs/ComplexIorData.hpp), so `"material": "Au"` means the same in both renderers. */
#ifndef METALS_H
#define METALS_H

#include "base/vecmath.h"

/* False if the name is unknown (names are case-sensitive, as in Tungsten). */
bool metal_lookup(const char *name, rgb *eta, rgb *k);

#endif
