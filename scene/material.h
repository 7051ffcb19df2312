// Surface appearance of a solid or surface: Whitted's material model
// (docs/theory.md, "Shading") in any combination. Colours are
// linear RGB (as in POV-Ray 3.7 with assumed_gamma 1): the renderer shades
// in linear light and encodes 8-bit images as sRGB.
#pragma once

#include <memory>

#include "engine/solid.h"
#include "scene/texture.h"

namespace csgray::detail {

struct Material {
  dvec3 color{0.8, 0.8, 0.8};
  TexturePtr texture;       // when set, gives the colour in place of color
  double ambient = 0.1;     // share of the colour seen without any light (Ka)
  double diffuse = 0.9;     // Lambert factor (Kd)
  double specular = 0.0;    // Phong highlight factor (Ks)
  double shininess = 20.0;  // Phong exponent f of cos^f β (Phong 1975)
  double reflection = 0.0;  // share of the mirrored ray's colour
  // Share of the light behind that passes through one stretch of the solid
  // (I = k·I_behind), tinted by filter.
  double transparency = 0.0;
  dvec3 filter{1.0, 1.0, 1.0};
  // The depth of the solid through which its filter is reached: a stretch
  // of length d passes filter^(d / filterDistance), the transmissivity
  // raised to the distance travelled of Hall and Greenberg's model (the
  // Beer-Lambert law), so thick glass is darker than thin. 0: the filter
  // applies once per stretch, whatever its length.
  double filterDistance = 0.0;
  // Hall's transmitted highlight: a light seen through a transparent
  // surface, or through the face by which an eye ray leaves a transparent
  // solid, as Phong's lobe cos^shininess about the way the eye ray goes on
  // past it, times this factor (raytrace/renderer.cpp).
  double transmittedSpecular = 0.0;
  double ior = 1.0;      // index of refraction; 1 passes rays straight through
  bool fresnel = false;  // weigh reflection and refraction by the Fresnel equations
  // Blur of the mirrored and refracted rays, a roughness in [0, 1]: 0 is a
  // perfect mirror, more spreads each ray over a wider lobe
  // (raytrace/scattering.h).
  double gloss = 0.0;
  // Light the surface gives off (linear RGB, >= 0): added to what it
  // shows, and what indirect light carries to other surfaces.
  dvec3 emission{0.0};
  // Bumps: the surface shaded as if raised by bumpDepth times the
  // brightness (luminance) of this pattern at each point, so that its
  // normal tilts by the height's gradient (Blinn, "Simulation of Wrinkled
  // Surfaces", SIGGRAPH '78); the shape itself is not changed.
  TexturePtr bumps;
  double bumpDepth = 0.1;

  // The colour at a point in texture space with the normal there.
  dvec3 colorAt(const dvec3& texturePoint, const dvec3& textureNormal) const {
    return texture ? texture->colorAt(texturePoint, textureNormal) : color;
  }
  bool refracts() const { return transparency > 0.0 && ior != 1.0; }
  // The same look: every field equal, the same texture.
  bool operator==(const Material&) const = default;
};

using MaterialPtr = std::shared_ptr<const Material>;

// Checks a material as the script's material{} does, in the order of its
// parameters (the colour only when there is no texture). Throws
// std::invalid_argument ("material: ambient must be in [0, 1]").
void checkMaterial(const Material& material);

// The solid with the material: on a primitive it replaces the primitive's
// own; on a boolean it goes to every primitive below that has none, so that
// parts given their own colour keep it.
SolidPtr solidWithMaterial(const SolidPtr& solid, const MaterialPtr& material);

}  // namespace csgray::detail
