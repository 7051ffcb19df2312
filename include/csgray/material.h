// What a surface looks like: materials, and textures that vary the colour
// over it. Colours are linear RGB. The parameters and their ranges are those
// of the script's material{} and textures (docs/script.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "csgray/types.h"

namespace csgray {

namespace detail {
class Texture;
struct Access;
}  // namespace detail

// A colour that varies over a surface, as a function of the point in
// texture space: the world as it was when the material was given to a
// solid or surface, so that a texture moves with the part moved later.
class CSGRAY_API Texture {
 public:
  // Where the pattern sits: scaled, then rotated (degrees about x, then y,
  // then z), then translated.
  struct Placement {
    std::optional<Vec3> scale, rotate, translate;
  };
  // The colours of a pattern: first at 0 and second at 1, or, for every
  // pattern but the checker, `stops` when given (2 to 256, places in
  // [0, 1] in order: POV-Ray's color_map), linear between them; first and
  // second are then not used.
  struct Stop {
    double at;
    Vec3 color;
  };
  struct Colors {
    Vec3 first, second;
    std::vector<Stop> stops = {};
  };
  // How a bitmap wraps onto points (u, v in [0, 1), repeating).
  enum class Mapping {
    Planar,       // u = x, v = y
    Spherical,    // longitude and latitude about the origin
    Cylindrical,  // angle about z, and z
    Box,          // planar onto the face of the unit cube the normal picks
  };
  enum class Noise {
    Perlin,      // Perlin noise: one octave (octaves is not used)
    Turbulence,  // the sum of |noise| over octaves
    Marble,      // veins: sin(x + turbulence · strength)
    Wood,        // rings about the z axis, disturbed by turbulence
  };

  // Cubes of edge size in the first and second colour (default: white and
  // dark grey).
  static Texture checker(const std::optional<Colors>& colors = std::nullopt, double size = 1.0,
                         const Placement& placement = {});
  // The first colour at `from`, the second at `to`, blending along the
  // line between them and constant beyond (default: white to dark grey).
  static Texture gradient(const std::optional<Colors>& colors = std::nullopt,
                          const Vec3& from = {0.0, 0.0, 0.0}, const Vec3& to = {0.0, 0.0, 1.0},
                          const Placement& placement = {});
  // Fractal noise blending the two colours (defaults depend on the kind);
  // octaves from 1 to 16, strength >= 0.
  static Texture noise(Noise kind, const std::optional<Colors>& colors = std::nullopt,
                       int octaves = 6, double strength = 4.0, const Placement& placement = {});
  // The Mandelbrot set, or the Julia set of c, in the xy plane (the
  // script's mandelbrot{} and julia{}): points that stay within radius 2
  // for `iterations` steps (1 to 10000) take `inside`, the others blend the
  // colours by their smooth escape count.
  enum class Fractal { Mandelbrot, Julia };
  static Texture fractal(Fractal kind, const std::optional<Colors>& colors = std::nullopt,
                         const Vec3& inside = {0.0, 0.0, 0.0}, int iterations = 100,
                         double cx = -0.123, double cy = 0.745, const Placement& placement = {});
  // An image file (PNG, JPEG, EXR, ...) wrapped by the mapping.
  static Texture image(const std::string& path, Mapping mapping = Mapping::Planar,
                       const Placement& placement = {});

  // The colour at a point of texture space where the surface has the given
  // normal.
  Vec3 colorAt(const Vec3& point, const Vec3& normal) const;

 private:
  explicit Texture(std::shared_ptr<const detail::Texture> impl);
  detail::Shared<detail::Texture> impl_;
  friend struct detail::Access;
};

// Every field has the script's default; Scene and Solid::material check
// the ranges.
struct Material {
  Vec3 color{0.8, 0.8, 0.8};       // components >= 0
  std::optional<Texture> texture;  // when set, gives the colour in place of color
  double ambient = 0.1;            // [0, 1]: share of the colour seen without light
  double diffuse = 0.9;            // [0, 1]: Lambert factor
  double specular = 0.0;           // [0, 1]: Phong highlight
  double shininess = 20.0;         // > 0: Phong exponent
  double reflection = 0.0;         // [0, 1]: share of the mirrored ray's colour
  double transparency = 0.0;       // [0, 1]: share of the light behind that passes
  Vec3 filter{1.0, 1.0, 1.0};      // components in [0, 1]: tint of the light passing
  double filterDistance = 0.0;  // >= 0: depth of a solid through which filter is reached (0: once)
  double transmittedSpecular = 0.0;  // [0, 1]: highlight of lights seen through the surface
  double ior = 1.0;                  // 1 to 10: index of refraction
  bool fresnel = false;              // weigh reflection and refraction by Fresnel's equations
  double gloss = 0.0;                // [0, 1]: blur of the mirrored and refracted rays
  Vec3 emission{0.0, 0.0, 0.0};      // components >= 0: light the surface gives off
  // Bumps: shaded as if raised by bumpDepth times the pattern's brightness
  // (the shape is not changed).
  std::optional<Texture> bumps = std::nullopt;
  double bumpDepth = 0.1;  // finite; below 0, dents
};

}  // namespace csgray
