// Colours written as text, as CSS writes them: the named colours of CSS
// Color Module Level 4 (section 6.1, "Named Colors": the X11 names, with
// gray, green, maroon and purple as the web has them) and hex "#rgb" and
// "#rrggbb". Text colours are sRGB-encoded, as they are everywhere else,
// and come out here as the linear RGB the renderer shades in
// (docs/script.md, "Colours"); a triple {r, g, b} in a script stays linear.
#pragma once

#include <string>
#include <string_view>

#include "engine/ray.h"

namespace csgray::detail {

// One sRGB-encoded component in [0, 1] to linear light: the piecewise
// curve of IEC 61966-2-1 (a line near black, a 2.4 power above 0.04045).
double srgbToLinear(double encoded);
dvec3 srgbToLinear(const dvec3& encoded);

// The linear colour a name ("red", "SteelBlue": case and spaces do not
// matter) or a hex code ("#ff8800", "#f80") stands for. Throws
// std::invalid_argument naming what ("material: color"), the text, and the
// nearest name when one is near: "material: color 'redd' is not a colour
// name (did you mean red?)".
dvec3 parseColor(std::string_view text, const std::string& what);

}  // namespace csgray::detail
