// How far a point lies from the exact model's surface, and how far the
// exported mesh may be from it there, for csgray check. Every distance is an
// upper bound, found at a boundary point of the part: along 13 lines through
// the point, by projection onto the faces near it, or by a search along many
// lines; what is allowed is the tolerance, more where faces meet at a crease,
// a corner or a tangential wedge.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

#include "check/check_report.h"
#include "engine/primitive.h"
#include "engine/solid.h"

namespace csgray::detail {

// A mesh point further than this many tolerances from the exact surface is
// reported as this far: the check has failed by then.
inline constexpr double kFidelityReach = 100.0;

// The outward normal of the solid at a boundary.
dvec3 outwardNormal(const Boundary& b, const dvec3& p);

class ExactDistance {
 public:
  // The box is the one the check samples: its diagonal sets the scale of
  // the small offsets below.
  ExactDistance(const Solid& solid, const CheckOptions& options, const Bounds& box);

  double epsilon() const { return epsilon_; }

  // The distance from p to the exact surface, estimated along 13 lines
  // through p (the axes, the face diagonals and the body diagonals of a
  // cube): a boundary at Δt with unit normal n is Δt·|n·d| away if the
  // surface is flat there (exact for a plane, off by O(δ²/radius) on a
  // curved one); the least over the boundaries. Faces a line grazes
  // (|n·d| < kGrazing) are left to the other lines. Several lines are
  // needed near an edge of the solid, where the nearest point is on the
  // edge and the lines along the axes may all miss the faces beside it.
  //
  // The lines pass a hair's breadth (1e-8 of the box) off p in a skew
  // direction: a mesh point found by an axis ray lies on an axis-aligned
  // face more often than not, and a line in the plane of a face grazes it.
  //
  // Only faces within `reach` of p are looked for, and a distance beyond
  // it is given as `reach`: the callers need no more, and a short line
  // meets few of a large boolean's operands.
  double surfaceDistance(const dvec3& p, double reach) const;

  // An upper bound on the distance from p to the exact surface, from
  // points of it found near p by projection rather than along lines: for
  // a mesh point that the lines of surfaceDistance put beyond what is
  // allowed. Those lines miss an edge where two faces meet at a shallow
  // angle (a sphere cut from a plane face leaves a wedge a few degrees
  // wide), when p lies on the part of a face that the other surface cut
  // off: the nearest boundary is then the edge, in a thin cone of
  // directions. So: for each face of a primitive near p, its point nearest
  // p, and for each pair of such faces, a point of the curve where they
  // meet (alternating projections, von Neumann 1950, which converge for
  // faces that cross); each point counts if the part's inside and outside
  // both come within a hair of it. Sound whatever it finds: the distance
  // to a boundary point is at least the distance to the surface.
  struct Projected {
    double distance;  // to a boundary point found, or the reach
    double allowed;   // what the mesh may be off there (see allowance)
  };
  Projected distanceByProjection(const dvec3& p, double reach) const;

  // An upper bound on the distance from p to the exact surface, searched
  // for along many lines through p, with what is allowed there: for a mesh
  // point that neither the 13 lines nor projection put within what is
  // allowed. A face cut down to a small patch by other operands (a torus
  // less a box and a cylinder) can lie nearer p than anything those find:
  // the lines pass beside the patch, and the point of the whole face
  // nearest p lies off the part. The lines cover the sphere of directions
  // kSearchLines times, then close in on the few best, each round half as
  // widely; every boundary they meet is a point of the exact surface, so
  // the bound is sound. The faces they meet within a few tolerances of the
  // nearest make the creases and corners of cornerAllowance.
  Projected distanceBySearch(const dvec3& p, double reach) const;

  // Is p within what the mesh may be off the exact surface there, where
  // the two may classify it differently?
  bool withinBand(const dvec3& p) const;

  // How far the mesh may be from the exact surface at p, found d away:
  // the tolerance, or more where two faces meet at a crease. Each face's
  // mesh is within the tolerance of the face, and so may be offset by it;
  // where faces with normals an angle φ apart meet, offsetting both by the
  // tolerance moves their crease by tolerance / cos(φ/2) (√2 of it at a
  // right angle), and the mesh of a boolean is made of such offset faces.
  // Faces of other primitives (or other faces of p's) met within a few
  // tolerances of p along the 13 lines make a crease.
  double allowance(const dvec3& p, double d) const;

 private:
  // Alternating projections close in on the curve where two faces meet by
  // a factor cos²θ a round for faces θ apart: 2 000 rounds take faces 5°
  // apart from a reach away to within 1e-6 of it.
  static constexpr int kMaxProjections = 2000;

  // What the mesh may be off where faces with these outward normals meet.
  // Each face's mesh may be offset by the tolerance: two faces move their
  // crease by creaseStretch tolerances, and
  // three faces move their corner to x with nᵢ·x = tolerance for each,
  // x = N⁻¹(1, 1, 1)·tolerance for the matrix N of their normals (√3 ×
  // the tolerance at a cube's corner). Ten tolerances at most, as for a
  // knife edge.
  static double cornerAllowance(const std::vector<dvec3>& normals, double tolerance);

  // Two faces that meet tangentially (a torus round a cylinder, a sphere on
  // a plane) close a wedge that no offset of the tolerance bounds: each
  // face's mesh may stand a tolerance into it, so the meshes fill it as far
  // as its two sides are less than two tolerances apart, and the crease of
  // the mesh lies that far from the exact one (about 2√(tolerance·r) for a
  // side of curvature radius r against a plane). This is that distance
  // from p, the nearest way out of the wedge: along each of 16 directions
  // of the faces' tangent plane, the two faces are projected on from points
  // ever further out until they stand two tolerances apart; a direction
  // along the crease never gets there, nor one where a face ends. Faces
  // that lie on each other (boxes face to face) never part: no wedge, 0.
  double wedgeDepth(const dvec3& p, const Primitive& a, std::uint32_t faceA, const Primitive& b,
                    std::uint32_t faceB) const;

  void collectPrimitives(const Solid& solid);

  // Moves x to the nearest crossing of the face by the line through x along
  // the face's normal there: x's foot on the face, exactly for planes and
  // spheres, near it on other surfaces. False if the line misses the face
  // within reach.
  static bool projectOnto(const Primitive& primitive, int face, dvec3& x, double reach);

  // If the part's inside and outside both come within a hair of x, a
  // direction from x into the inside. Asked at x moved a hair along each
  // (unit) normal and each sum and difference of two, each way: near a
  // curve where two faces meet, one of these lies in each of the four
  // wedges between them, however thin.
  std::optional<dvec3> insideNear(const dvec3& x, std::initializer_list<dvec3> normals) const;

  const Solid& solid_;
  const CheckOptions& options_;
  double epsilon_ = 0.0;  // boundaries this close coincide
  dvec3 nudge_{0.0};      // off the point where surfaceDistance measures
  double hair_ = 0.0;     // how far from a point insideNear looks: a thousandth of the tolerance
  std::vector<const Primitive*> primitives_;  // the part's leaves, for distanceByProjection
};

}  // namespace csgray::detail
