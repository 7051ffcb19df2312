// The look a bare solid gets, the one a CAD viewer shows (docs/script.md,
// "The default look"): a light background, soft from top to bottom, that
// through-holes show; three lights that move with the camera (a key light
// that casts shadows, a fill light and a rim light behind the part), so
// that faces turned differently differ in shade; and a shadow on the
// ground under the part, on a plane that shows nothing but that shadow.
// Scenes the script describes itself keep their own lights and background.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "engine/bounds.h"
#include "scene/scene.h"

namespace csgray::detail {

// The rays per pixel of a bare solid's render when the command line does
// not say (adaptive: spent only on pixels at edges; docs/cli.md).
inline constexpr int kCadLookSamples = 9;

class CadLook {
 public:
  // camera: the one the render uses (lights and background follow it),
  // for an image of the aspect ratio width / height; bounds: the scene's,
  // under which the ground lies (none if unbounded).
  CadLook(const CameraSpec& camera, double aspect, const Bounds& bounds);

  // Key, fill and rim, in that order; only the key light casts shadows.
  std::vector<Light> lights() const;

  // The background along a ray that meets nothing: lighter at the bottom
  // of the picture than at the top.
  dvec3 background(const Ray& ray) const;

  // The ground: the plane z = bounds.lo.z under the part (Z is up), seen
  // only where the camera is above it. Where a ray meets it within the
  // reach of the part's shadow, the point; else nothing: there the ground
  // is wholly lit and shows the background.
  std::optional<dvec3> groundPoint(const Ray& ray) const;

  // The rectangle of the ground (x and y, low and high corners) outside
  // which groundPoint finds nothing; false when there is no ground.
  bool groundRegion(dvec3& lo, dvec3& hi) const;
  double groundZ() const { return groundZ_; }

  // The sky light that casts the ground shadow: a disc high above the
  // part, sampled at kSkyPoints points spread evenly over it (Vogel's
  // spiral). The first kProbes points are spread over the disc: when they
  // all agree, the point is wholly lit or wholly in shadow and the others
  // need not be traced.
  static constexpr int kProbes = 4, kSkyPoints = 24;
  // The sky points that ground point p's shadow rays go to: the spiral
  // turned by an angle and its rings moved out by a share of their
  // spacing, both drawn from p's coordinates. With the same points for
  // every ground point, each point cast its own sharp shadow, and a wide
  // penumbra showed as 24 nested rings a few levels of grey apart; drawn
  // per point, the steps fall in different places at neighbouring points
  // and the penumbra shades off smoothly, with a grain that the ground
  // shadow's grid averages out (raytrace/ground_shadow_grid.h). The same
  // point always gets the same sky, so a render is the same every time.
  // Not drawn, the points are the spiral itself, the same for every
  // point: for a pixel traced on its own (beside a sharp step of the
  // shadow, or off the grid), where no average would take the grain out.
  std::array<dvec3, kSkyPoints> skyPointsFor(const dvec3& p, bool drawn = true) const;
  // The background times this where all the sky is hidden.
  static constexpr double kShadowDarkness = 0.45;
  // The colour of ground seen under the given share of hidden sky.
  dvec3 shadowed(const dvec3& background, double hidden) const {
    return background * (1.0 - kShadowDarkness * hidden);
  }

 private:
  dvec3 eye_, lookAt_, forward_, right_, up_;
  double tanHalfHeight_;  // perspective: tan of half the vertical view angle
  bool orthographic_;
  double halfHeight_;  // orthographic: half the screen's height
  bool hasGround_ = false;
  double groundZ_ = 0.0;
  Bounds bounds_;
  dvec3 skyCentre_{0.0};
  double skyRadius_ = 0.0;
  // The share of the way up to the sky at the top of the bounds.
  double topShare_ = 0.0;
  // The spiral's points on the unit disc before the turn: the direction
  // of each (cos, sin), its ring and the number of rings on its spiral.
  struct SpiralPoint {
    double cos, sin;
    int ring, rings;
  };
  std::array<SpiralPoint, kSkyPoints> spiral_{};
};

}  // namespace csgray::detail
