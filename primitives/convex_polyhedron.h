// A convex polyhedron: the intersection of half-spaces nᵢ·p <= dᵢ. Any
// number of planes from 1 to kMaxPlanes; the set may be unbounded (a wedge,
// a prism, a slab), but not empty when that can be proved. Face i of the
// solid is plane i (counted from 0 here, from 1 in messages, as the script
// counts), so a boundary's face is the index of the plane that set it.
//
// The five Platonic solids are convex polyhedra built from their face planes
// (platonicSolid below).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "primitives/primitive_shape.h"

namespace csgray::detail {

class ConvexPolyhedron : public PrimitiveShape<ConvexPolyhedron> {
 public:
  // The closed half-space normal·p <= offset. The normal need not be unit.
  struct Plane {
    dvec3 normal;
    double offset = 0.0;
  };

  // Spans cost O(planes) per ray and nothing bounds the count but memory,
  // so a limit keeps a typo (or a generated script) from making a part
  // that takes hours to render.
  static constexpr std::size_t kMaxPlanes = 10000;
  // Up to this many planes, bounds and emptiness are found exactly by
  // vertex enumeration, which is O(n⁴) in the worst case (every triple of
  // planes, each checked against all planes): some tens of ms at this size.
  static constexpr std::size_t kExactPlanes = 128;

  // Normalises the planes and checks them: a zero, infinite or NaN normal,
  // a non-finite offset, no planes, more than kMaxPlanes, or an empty
  // intersection throws std::invalid_argument naming kind (the script
  // function: "convex", "tetrahedron", ...) and the plane.
  explicit ConvexPolyhedron(const std::vector<Plane>& planes, std::string kind = "convex");
  // A bounded polyhedron whose vertices are known (a hull's): its box is
  // theirs and vertices() returns them, whatever the count of planes.
  ConvexPolyhedron(const std::vector<Plane>& planes, std::vector<dvec3> vertices, std::string kind);

  std::string kind() const override { return kind_; }
  // The planes with unit normals, in the order given.
  const std::vector<Plane>& planes() const { return *planes_; }
  // The vertices when the solid is bounded and has at most kExactPlanes
  // planes (each once); empty otherwise.
  const std::vector<dvec3>& vertices() const { return *vertices_; }

 protected:
  void objectSpans(const Ray& ray, SpanList& out) const override;
  bool objectContains(const dvec3& p) const override;
  dvec3 objectNormal(const dvec3& p, int face) const override;
  Bounds objectBounds() const override { return box_; }
  TriangleMesh objectTessellate(double tolerance, const Bounds& region) const override;

 private:
  // Shared, so that moving or colouring a part with thousands of planes
  // (which clones it) does not copy them.
  std::shared_ptr<const std::vector<Plane>> planes_;
  std::shared_ptr<const std::vector<dvec3>> vertices_;
  Bounds box_;
  std::string kind_;
};

// ---- The Platonic solids ------------------------------------------------------

// Each is centred at the origin and given by its circumradius R (the
// distance from the centre to every vertex). Orientations:
//   tetrahedron   a vertex at (0, 0, R), the opposite face on z = -R/3
//                 (normal -z), a base vertex in the xz plane at x > 0;
//   hexahedron    the cube with faces normal to the axes;
//   octahedron    vertices on the axes at ±R (|x| + |y| + |z| <= R);
//   dodecahedron  vertices (±1, ±1, ±1), (0, ±1/φ, ±φ) and their cyclic
//                 permutations, times R/√3;
//   icosahedron   vertices (0, ±1, ±φ) and their cyclic permutations,
//                 times R/√(1 + φ²);
// where φ = (1 + √5)/2: the coordinates tabulated by Coxeter, Regular
// Polytopes (3rd ed., 1973), §3.7, which put the dodecahedron and the
// icosahedron with the coordinate planes as mirror planes.
enum class Platonic { Tetrahedron, Hexahedron, Octahedron, Dodecahedron, Icosahedron };

struct PlatonicInfo {
  const char* name;  // the script function
  int faces, vertices;
  double inradius;  // r/R: distance of the faces from the centre
  double edge;      // a/R
};
const PlatonicInfo& platonicInfo(Platonic solid);

// The vertices at circumradius R, in the orientation above.
std::vector<dvec3> platonicVertices(Platonic solid, double R);
// The face planes: unit outward normals (the directions of the dual's
// vertices) at distance r = R·inradius.
std::vector<ConvexPolyhedron::Plane> platonicPlanes(Platonic solid, double R);
// The solid; R must be positive and finite (the message names info.name
// and "r", the script's parameter).
std::shared_ptr<ConvexPolyhedron> platonicSolid(Platonic solid, double R);

}  // namespace csgray::detail
