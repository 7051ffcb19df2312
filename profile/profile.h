// A profile: a region of the plane bounded by closed loops of straight
// segments, elliptic arcs and Bézier curves (the outlines of letters), filled by the even-odd rule
// (a point is inside when a ray from it crosses the loops an odd number of times), as OpenSCAD's
// polygon() with paths is. Circles are arcs, not polygons: the sweeps of a profile (extrusions,
// revolutions) are exact.
#pragma once

#include <cstdint>
#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <vector>

namespace csgray::detail {

using glm::dmat2;
using glm::dvec2;

// A 2D affine map: p ↦ linear · p + offset.
struct Affine2 {
  dmat2 linear{1.0};
  dvec2 offset{0.0};

  dvec2 apply(const dvec2& p) const { return linear * p + offset; }
  Affine2 then(const Affine2& next) const {  // next after this
    return {next.linear * linear, next.linear * offset + next.offset};
  }
};

// One edge of a loop. A segment runs from `from` to `to`. An arc is the
// points center + axes · (cos θ, sin θ) for θ from angle0 to angle1
// (angle1 < angle0 runs the other way round): a circle of radius r has
// axes r·I (or r times a rotation), an ellipse or a circle under a
// non-uniform scale has any invertible axes. `from` and `to` are the
// arc's ends, kept so that loops join exactly. A quadratic Bézier curve
// runs from `from` to `to` pulled towards control1; a cubic one towards
// control1, then control2 (profile/bezier.h: its points, bounds and
// crossings).
struct ProfileEdge {
  enum class Kind : std::uint8_t { Segment, Arc, Quadratic, Cubic };
  Kind kind = Kind::Segment;
  dvec2 from{0.0}, to{0.0};
  dvec2 center{0.0};
  dmat2 axes{1.0};
  double angle0 = 0.0, angle1 = 0.0;
  dvec2 control1{0.0}, control2{0.0};

  static ProfileEdge segment(const dvec2& a, const dvec2& b);
  static ProfileEdge arc(const dvec2& center, const dmat2& axes, double angle0, double angle1);
  static ProfileEdge quadratic(const dvec2& a, const dvec2& control, const dvec2& b);
  static ProfileEdge cubic(const dvec2& a, const dvec2& control1, const dvec2& control2,
                           const dvec2& b);
  bool bezier() const { return kind == Kind::Quadratic || kind == Kind::Cubic; }

  // The point at θ on an arc's ellipse.
  dvec2 arcPoint(double theta) const;
  // Is the arc a circle's (axes a multiple of a rotation or reflection)?
  bool circular() const;
  ProfileEdge transformed(const Affine2& map) const;
};

// A closed loop: each edge's `to` is the next one's `from`, the last's the
// first's.
struct ProfileLoop {
  std::vector<ProfileEdge> edges;
};

struct ProfileBounds {
  dvec2 lo{1e300}, hi{-1e300};
  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
  void include(const dvec2& p);
  void include(const ProfileBounds& b);
};

struct Profile {
  std::vector<ProfileLoop> loops;

  // Even-odd containment; a point on an edge may go either way.
  bool contains(const dvec2& p) const;
  ProfileBounds bounds() const;
  Profile transformed(const Affine2& map) const;
};

// The even-odd rule's pieces, for Profile::contains and for a sweep's own
// count over its index of edges, so that both count alike: does the
// half-line from p towards +x cross the segment a–b (half-open in y, so
// that a vertex shared by two edges counts once)? Is w, in the frame where
// an arc's ellipse is the unit circle, between the arc from angle0 to
// angle1 and its chord (the count crosses the chord, not the arc)?
bool halfLineCrossesSegment(const dvec2& p, const dvec2& a, const dvec2& b);
bool inUnitArcCap(const dvec2& w, double angle0, double angle1);

}  // namespace csgray::detail
