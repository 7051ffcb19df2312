// Surface appearance of a solid. Colours are linear RGB (as in POV-Ray 3.7
// with assumed_gamma 1): the renderer shades in linear light and encodes
// 8-bit images as sRGB.
#pragma once

#include <memory>

#include "modeler/ray.h"

namespace csgray {

struct Material {
  dvec3 color{0.8, 0.8, 0.8};
  double ambient = 0.1;  // share of the colour seen without any light (seed 001, 2.2.1: Koh)
  double diffuse = 0.9;  // Lambert factor κ (seed 000, 17.4.2; seed 001, 2.2.1: Kod)
};

using MaterialPtr = std::shared_ptr<const Material>;

}  // namespace csgray
