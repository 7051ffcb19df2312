// Light sources (docs/theory.md, "Shading"): coloured
// point lights of any intensity, Warn spot lights, and area lights (a
// rectangle or a sphere) that cast soft shadows through sampling.
#pragma once

#include <optional>

#include "engine/ray.h"

namespace csgray::detail {

struct Light {
  enum class Kind { Point, Spot, Rectangle, Sphere };
  Kind kind = Kind::Point;
  dvec3 position{0.0};  // the point; the centre of an area light
  dvec3 color{1.0};
  double intensity = 1.0;
  // Divide by the squared distance d². Off by default, so
  // that intensity 1 means full strength at any distance.
  bool inverseSquare = false;
  // Shadow rays test whether the light reaches a point. The fill and rim
  // lights of a bare solid's look (raytrace/cad_look.h) light everything,
  // as such lights do: a scene's lights always cast shadows.
  bool castsShadows = true;

  // Spot (Warn, "Lighting Controls for Synthetic Images", 1983): light along direction,
  // cos^exponent of the angle off the axis, nothing beyond coneDegrees off it;
  // from innerDegrees out to the cone's edge it fades to nothing (a soft
  // edge, POV-Ray's radius and falloff; innerDegrees ≥ coneDegrees: none).
  dvec3 direction{0.0, 0.0, -1.0};
  double coneDegrees = 30.0;
  double innerDegrees = 90.0;
  double exponent = 1.0;

  // Rectangle: position ± edgeU/2 ± edgeV/2. Sphere: radius about position.
  dvec3 edgeU{1.0, 0.0, 0.0}, edgeV{0.0, 1.0, 0.0};
  double radius = 1.0;
  int samples = 16;  // shadow rays per shaded point for an area light

  bool isArea() const { return kind == Kind::Rectangle || kind == Kind::Sphere; }
  // The number of points samplePoint is called for at each shaded point.
  // samples rounded to a square k², the strata of a k × k grid.
  int sampleCount() const;
  // Sample i of sampleCount() as seen from point p, with (u, v) in [0, 1)²
  // jittering it within its stratum.
  dvec3 samplePoint(int i, double u, double v, const dvec3& p) const;
  // The light's colour times intensity reaching p from the sample point s,
  // before shadows: spot cone and falloff, 1/d², and the share of one
  // sample of an area light.
  dvec3 radianceAt(const dvec3& p, const dvec3& s) const;
};

// A light as a user gives it, with the parameters of the script's
// point_light{}, spot_light{} (Spot), area_light{} (Rectangle) and
// sphere_light{} (Sphere); each kind uses its own and the common ones.
struct LightParams {
  Light::Kind kind = Light::Kind::Point;
  dvec3 position{0.0};  // pos: the point, or the centre of an area light
  dvec3 color{1.0};
  double intensity = 1.0;
  bool falloff = false;  // divide by the squared distance
  // Spot: aimed at lookAt or along direction (not both); neither: down -z.
  std::optional<dvec3> lookAt, direction;
  double angle = 30.0;          // degrees off the axis the cone reaches
  std::optional<double> inner;  // where its edge starts to fade; none: angle, a hard edge
  double exponent = 1.0;
  dvec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0};  // Rectangle: its edges
  double radius = 1.0;                       // Sphere
  double samples = 16.0;                     // Rectangle, Sphere: a whole number
};

// The light, checked as the script checks it, with messages that name the
// script function ("spot_light: angle must be between 0 and 90 degrees").
// Throws std::invalid_argument.
Light makeLight(const LightParams& params);
// The script function of a kind of light: "point_light", ...
const char* lightFunction(Light::Kind kind);

}  // namespace csgray::detail
