#include "scene/hull_shapes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "primitives/box.h"
#include "primitives/cgal/point_hull.h"
#include "primitives/convex_polyhedron.h"
#include "primitives/cylinder.h"
#include "primitives/linear_extrusion.h"
#include "primitives/mesh_solid.h"
#include "primitives/rounded_polytope.h"
#include "primitives/sphere.h"
#include "scene/shapes.h"
#include "scene/swept_hulls.h"

namespace csgray::detail {

namespace {

// Hulls with more faces than this are meshes rather than planes: a ray
// costs O(planes) in a convex polyhedron and O(log faces) in a mesh.
constexpr std::size_t kMostPlanes = 256;
// The most points a sum of two meshes may make before its hull.
constexpr double kMostSumPoints = 4e6;

std::invalid_argument error(const std::string& function, const std::string& what) {
  return std::invalid_argument(function + ": " + what);
}

// The scale of a frame that scales alike along every axis (besides
// turning, mirroring and moving), which keeps a ball a ball.
std::optional<double> uniformScale(const Affine& frame) {
  glm::dmat3 m(frame.worldFromObject());
  double s = glm::length(m[0]);
  for (int i = 0; i < 3; ++i) {
    if (std::abs(glm::length(m[i]) - s) > 1e-12 * s) return std::nullopt;
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(m[i], m[j])) > 1e-12 * s * s) return std::nullopt;
  }
  return s;
}

std::optional<Ball> ballOf(const Primitive& p) {
  const auto* sphere = dynamic_cast<const Sphere*>(&p);
  std::optional<double> s = uniformScale(p.frame());
  if (!sphere || !s) return std::nullopt;
  return Ball{p.frame().pointToWorld(dvec3(0.0)), sphere->radius() * *s};
}

// The corners of a polyhedral primitive in world space (a mesh's points);
// none for a curved one.
std::vector<dvec3> cornersOf(const Primitive& p) {
  std::vector<dvec3> corners;
  if (const auto* box = dynamic_cast<const Box*>(&p)) {
    const dvec3& s = box->size();
    for (int i = 0; i < 8; ++i)
      corners.push_back({i & 1 ? s.x : 0.0, i & 2 ? s.y : 0.0, i & 4 ? s.z : 0.0});
  } else if (const auto* convex = dynamic_cast<const ConvexPolyhedron*>(&p)) {
    corners = convex->vertices();
  } else if (const auto* mesh = dynamic_cast<const MeshSolid*>(&p)) {
    corners = mesh->points();
  } else if (const auto* sweep = dynamic_cast<const LinearExtrusion*>(&p)) {
    // A polygon's sides sweep planes: the corners at the bottom, and
    // scaled at the top.
    const auto loops = sweep->polygonLoops();
    if (!loops) return {};  // curved or twisted: no corners
    const double z0 = sweep->bottom(), z1 = z0 + sweep->height(), s = sweep->scale().x;
    for (const std::vector<dvec2>& loop : *loops)
      for (const dvec2& u : loop) {
        corners.push_back({u.x, u.y, z0});
        if (s > 0.0) corners.push_back({s * u.x, s * u.y, z1});
      }
    if (s == 0.0) corners.push_back({0.0, 0.0, z1});  // a pyramid's apex
  }
  for (dvec3& c : corners) c = p.frame().pointToWorld(c);
  return corners;
}

// The volume of a primitive convexPolytopeOf must not exceed with its
// hull, where its corners need not be convex: a mesh's, or an extrusion's
// (a frustum of similar sections, h (A + √(A·s²A) + s²A) / 3).
std::optional<double> volumeToHold(const Primitive& p) {
  const double det = std::abs(glm::determinant(glm::dmat3(p.frame().worldFromObject())));
  if (const auto* mesh = dynamic_cast<const MeshSolid*>(&p)) return mesh->volume() * det;
  if (const auto* sweep = dynamic_cast<const LinearExtrusion*>(&p)) {
    const Region& region = *sweep->region();
    const double a = area(evaluate(region, evaluationTolerance(region))), s = sweep->scale().x;
    return sweep->height() * a * (1.0 + s + s * s) / 3.0 * det;
  }
  return std::nullopt;
}

// The volume of a solid polytope: a cone from the origin over each face,
// of height its plane's offset.
double volumeOf(const Polytope& p) {
  double volume = 0.0;
  for (const Polytope::Face& f : p.faces) {
    dvec3 area(0.0);
    const dvec3& a = p.vertices[f.loop[0]];
    for (std::size_t i = 1; i + 1 < f.loop.size(); ++i)
      area += glm::cross(p.vertices[f.loop[i]] - a, p.vertices[f.loop[i + 1]] - a);
    volume += f.offset * glm::dot(area, f.normal) / 6.0;
  }
  return volume;
}

// The hull of a convex polyhedral primitive's corners: a mesh is convex
// when its hull holds no more than it does.
std::optional<Polytope> convexPolytopeOf(const Primitive& p) {
  std::vector<dvec3> corners = cornersOf(p);
  if (corners.empty()) return std::nullopt;
  Polytope hull = pointHull(corners);
  if (const std::optional<double> own = volumeToHold(p))
    if (hull.dimension < 3 || volumeOf(hull) > *own * (1.0 + 1e-9)) return std::nullopt;
  return hull;
}

// Is the primitive convex? Polyhedra as above; the quadric and rounded
// shapes that are.
bool convex(const Primitive& p) {
  if (dynamic_cast<const Sphere*>(&p) || dynamic_cast<const Cylinder*>(&p) ||
      dynamic_cast<const RoundedPolytope*>(&p))
    return true;
  return convexPolytopeOf(p).has_value();
}

// "takes shapes and unions of them, not an intersection": what a hull or
// a sum cannot take, named with its article.
std::string notAShape(const std::string& kind) {
  const bool vowel = !kind.empty() && std::string("aeiou").find(kind[0]) != std::string::npos;
  return std::string("takes shapes and unions of them, not ") + (vowel ? "an " : "a ") + kind;
}

// The leaves of unions of bounded primitives.
void collectLeaves(const SolidPtr& solid, const std::string& function,
                   std::vector<const Primitive*>& out) {
  if (const auto* node = dynamic_cast<const Boolean*>(solid.get())) {
    if (node->op() != Boolean::Op::Union) throw error(function, notAShape(node->kind()));
    for (const SolidPtr& child : node->children()) collectLeaves(child, function, out);
    return;
  }
  const auto* p = dynamic_cast<const Primitive*>(solid.get());
  if (!p) throw error(function, notAShape(solid->kind()));
  if (!solid->bounds().finite()) throw error(function, "the " + solid->kind() + " is unbounded");
  out.push_back(p);
}

// A solid polytope as a solid: planes, or a mesh when it has many faces.
SolidPtr polyhedronOf(const Polytope& p, const std::string& function) {
  if (p.dimension < 3) throw error(function, "the result is flat: it has no volume");
  if (p.faces.size() <= kMostPlanes) {
    std::vector<ConvexPolyhedron::Plane> planes;
    for (const Polytope::Face& f : p.faces) planes.push_back({f.normal, f.offset});
    return Primitive::create<ConvexPolyhedron>(planes, p.vertices, function);
  }
  // MeshSolid takes OpenSCAD's clockwise faces.
  std::vector<std::vector<std::int64_t>> faces;
  for (const Polytope::Face& f : p.faces) faces.emplace_back(f.loop.rbegin(), f.loop.rend());
  return Primitive::create<MeshSolid>(p.vertices, faces);
}

// A cylinder (not a cone) under a frame that keeps its shape.
struct Rod {
  dvec3 base, axis;  // axis: unit, from the base to the top
  double length, radius;
};

std::optional<Rod> rodOf(const Primitive& p) {
  const auto* c = dynamic_cast<const Cylinder*>(&p);
  std::optional<double> s = uniformScale(p.frame());
  if (!c || !s || c->r1() != c->r2()) return std::nullopt;
  dvec3 base = p.frame().pointToWorld(dvec3(0.0));
  dvec3 top = p.frame().pointToWorld({0.0, 0.0, c->height()});
  return Rod{base, glm::normalize(top - base), *s * c->height(), *s * c->r1()};
}

// Rods along one axis that start and end at the same heights along it:
// their hull is the hull of their discs, extruded.
SolidPtr rodHull(const std::vector<Rod>& rods, double size) {
  const AxisFrame frame(rods[0].axis);
  const double from = glm::dot(rods[0].base, frame.a), to = from + rods[0].length;
  std::vector<Disc> discs;
  for (const Rod& rod : rods) {
    double start = glm::dot(rod.base, frame.a),
           end = glm::dot(rod.base + rod.length * rod.axis, frame.a);
    bool parallel = glm::length(glm::cross(rod.axis, frame.a)) <= 1e-12;
    double lo = std::min(start, end), hi = std::max(start, end);
    if (!parallel || std::abs(lo - from) > 1e-12 * size || std::abs(hi - to) > 1e-12 * size)
      return nullptr;
    discs.push_back({{glm::dot(rod.base, frame.u), glm::dot(rod.base, frame.w)}, rod.radius});
  }
  return extrudedDiscHull(discs, frame, from, to);
}

// A polytope that is a prism along the rod's axis (each face along it or
// across it) plus the rod: the prism's section grown by the rod's radius
// (the hull of discs about its corners), over the sum of their lengths.
SolidPtr prismPlusRod(const Polytope& p, const Rod& rod) {
  const AxisFrame frame(rod.axis);
  for (const Polytope::Face& f : p.faces) {
    double along = std::abs(glm::dot(f.normal, frame.a));
    if (along > 1e-12 && along < 1.0 - 1e-12) return nullptr;
  }
  double lo = kInfinity, hi = -kInfinity;
  std::vector<Disc> discs;
  for (const dvec3& v : p.vertices) {
    dvec3 q = v + rod.base;
    lo = std::min(lo, glm::dot(v, frame.a));
    hi = std::max(hi, glm::dot(v, frame.a));
    discs.push_back({{glm::dot(q, frame.u), glm::dot(q, frame.w)}, rod.radius});
  }
  double start = glm::dot(rod.base, frame.a);
  return extrudedDiscHull(discs, frame, lo + start, hi + start + rod.length);
}

// The points within r of the polytope, by its dimension: a ball, a
// capsule, a rounded plate or solid.
SolidPtr rounded(const Polytope& p, double r, const std::string& kind) {
  if (p.dimension == 0) return sphereAt({p.vertices[0], r});
  if (p.dimension == 1) return twoBallHull({p.vertices[0], r}, {p.vertices[1], r});
  return Primitive::create<RoundedPolytope>(p, r, kind);
}

// The points of a convex primitive within kHullTolerance·size of it: its
// corners, or its mesh's points (of its hull only).
std::vector<dvec3> pointsOf(const Primitive& p, double size) {
  std::vector<dvec3> corners = cornersOf(p);
  if (!corners.empty()) return corners;
  TriangleMesh mesh = p.tessellate(kHullTolerance * size, p.bounds());
  return pointHull(mesh.points).vertices;
}

double sizeOf(const std::vector<const Primitive*>& leaves) {
  Bounds box;
  for (const Primitive* p : leaves) box.include(p->bounds());
  return glm::length(box.size());
}

// The sum of two convex primitives from their meshes: the hull of the
// sums of their points (the sum of two convex hulls is the hull of the
// pairwise sums of their points).
SolidPtr sumOfMeshes(const Primitive& a, const Primitive& b, double size) {
  std::vector<dvec3> pa = pointsOf(a, size), pb = pointsOf(b, size);
  if (double(pa.size()) * double(pb.size()) > kMostSumPoints) {
    throw error("minkowski", "the " + a.kind() + " and the " + b.kind() +
                                 " are too finely curved to sum (" + std::to_string(pa.size()) +
                                 " × " + std::to_string(pb.size()) + " points)");
  }
  std::vector<dvec3> sums;
  sums.reserve(pa.size() * pb.size());
  for (const dvec3& u : pa)
    for (const dvec3& v : pb) sums.push_back(u + v);
  return polyhedronOf(pointHull(sums), "minkowski");
}

// A convex primitive plus a ball: exact for polyhedra, rounded polytopes
// and cylinders under frames that keep their shape.
SolidPtr plusBall(const Primitive& p, const Primitive& ballShape, const Ball& ball, double size) {
  const std::string function = "minkowski";
  std::optional<double> scale = uniformScale(p.frame());
  if (const auto* r = dynamic_cast<const RoundedPolytope*>(&p); r && scale) {
    std::vector<dvec3> corners;
    for (const dvec3& v : r->polytope().vertices)
      corners.push_back(p.frame().pointToWorld(v) + ball.centre);
    return rounded(pointHull(corners), *scale * r->radius() + ball.radius, function);
  }
  if (const auto* c = dynamic_cast<const Cylinder*>(&p); c && scale && c->r1() == c->r2()) {
    // (sQC + t) ⊕ B(c, r) = Q(sC ⊕ B(0, r)) + t + c for a rotation Q, and
    // sC ⊕ B(0, r) is the rounded cylinder from z = −r.
    double r = ball.radius;
    SolidPtr sum = roundedCylinder(*scale * c->r1() + r, *scale * c->height() + 2.0 * r, r);
    glm::dmat4 m = p.frame().worldFromObject();
    for (int i = 0; i < 3; ++i) m[i] /= *scale;
    m[3] += glm::dvec4(ball.centre, 0.0);
    return sum->transformed(Affine::translation({0.0, 0.0, -r}))
        ->transformed(Affine::fromMatrix(m));
  }
  if (std::optional<Polytope> hull = convexPolytopeOf(p)) {
    for (dvec3& v : hull->vertices) v += ball.centre;
    for (Polytope::Face& f : hull->faces) f.offset += glm::dot(f.normal, ball.centre);
    return rounded(*hull, ball.radius, function);
  }
  return sumOfMeshes(p, ballShape, size);
}

SolidPtr minkowskiPair(const SolidPtr& a, const SolidPtr& b) {
  const std::string function = "minkowski";
  // (A₁ ∪ A₂) ⊕ B = (A₁ ⊕ B) ∪ (A₂ ⊕ B).
  for (const SolidPtr* side : {&a, &b}) {
    const auto* node = dynamic_cast<const Boolean*>(side->get());
    if (!node) continue;
    if (node->op() != Boolean::Op::Union) throw error(function, notAShape(node->kind()));
    const SolidPtr& other = side == &a ? b : a;
    std::vector<SolidPtr> parts;
    for (const SolidPtr& child : node->children()) parts.push_back(minkowskiPair(child, other));
    return booleanShape(Boolean::Op::Union, std::move(parts));
  }
  std::vector<const Primitive*> leaves;
  collectLeaves(a, function, leaves);
  collectLeaves(b, function, leaves);
  const Primitive& pa = *leaves[0];
  const Primitive& pb = *leaves[1];
  std::optional<Ball> ballA = ballOf(pa), ballB = ballOf(pb);
  if (ballA && ballB)
    return sphereAt({ballA->centre + ballB->centre, ballA->radius + ballB->radius});
  for (const Primitive* p : {&pa, &pb}) {
    if (convex(*p)) continue;
    if (dynamic_cast<const MeshSolid*>(p)) {
      throw error(function,
                  "the polyhedron is not convex: give it as a union of convex pieces, "
                  "whose sums are joined");
    }
    // What to do instead: pieces, and for an extruded profile its offset,
    // which is OpenSCAD's usual way to round one.
    throw error(function, "the " + p->kind() +
                              " is not convex; its sum is not supported: give it as a " +
                              "union of convex pieces, whose sums are joined" +
                              (p->kind() == "linear_extrude"
                                   ? ", or round the profile with offset{r=...} before extruding it"
                                   : ""));
  }
  double size = sizeOf(leaves);
  if (ballB) return plusBall(pa, pb, *ballB, size);
  if (ballA) return plusBall(pb, pa, *ballA, size);
  std::optional<Polytope> polyA = convexPolytopeOf(pa), polyB = convexPolytopeOf(pb);
  std::optional<Rod> rodA = rodOf(pa), rodB = rodOf(pb);
  if (polyA && rodB && polyA->dimension == 3)
    if (SolidPtr prism = prismPlusRod(*polyA, *rodB)) return prism;
  if (polyB && rodA && polyB->dimension == 3)
    if (SolidPtr prism = prismPlusRod(*polyB, *rodA)) return prism;
  if (polyA && polyB) {
    std::vector<dvec3> sums;
    for (const dvec3& u : polyA->vertices)
      for (const dvec3& v : polyB->vertices) sums.push_back(u + v);
    return polyhedronOf(pointHull(sums), function);
  }
  return sumOfMeshes(pa, pb, size);
}

void requireSide(const char* function, const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << function << ": " << name << " must be a positive finite number (got " << value << ")";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

SolidPtr hullShape(const std::vector<SolidPtr>& operands) {
  const std::string function = "hull";
  if (operands.empty()) throw error(function, "needs at least one solid");
  // The leaves in the world's frame: instances multiplied out (and kept
  // alive while the leaves are read).
  std::vector<SolidPtr> placed;
  for (const SolidPtr& s : operands) placed.push_back(flattened(s));
  std::vector<const Primitive*> leaves;
  for (const SolidPtr& s : placed) collectLeaves(s, function, leaves);
  std::vector<Ball> balls;
  for (const Primitive* p : leaves)
    if (std::optional<Ball> b = ballOf(*p)) balls.push_back(*b);
  if (balls.size() == leaves.size()) {
    // Balls of one radius r: the points within r of their centres' hull.
    const double r = balls[0].radius;
    bool alike = std::all_of(balls.begin(), balls.end(),
                             [&](const Ball& b) { return std::abs(b.radius - r) <= 1e-12 * r; });
    if (alike) {
      std::vector<dvec3> centres;
      for (const Ball& b : balls) centres.push_back(b.centre);
      return rounded(pointHull(centres), r, function);
    }
    if (balls.size() == 2) return twoBallHull(balls[0], balls[1]);
  }
  const double size = sizeOf(leaves);
  std::vector<Rod> rods;
  for (const Primitive* p : leaves)
    if (std::optional<Rod> rod = rodOf(*p)) rods.push_back(*rod);
  if (rods.size() == leaves.size())
    if (SolidPtr extruded = rodHull(rods, size)) return extruded;
  std::vector<dvec3> points;
  for (const Primitive* p : leaves) {
    std::vector<dvec3> some = pointsOf(*p, size);
    points.insert(points.end(), some.begin(), some.end());
  }
  return polyhedronOf(pointHull(points), function);
}

SolidPtr minkowskiShape(const std::vector<SolidPtr>& operands) {
  if (operands.empty()) throw error("minkowski", "needs at least one solid");
  SolidPtr sum = flattened(operands[0]);
  for (std::size_t i = 1; i < operands.size(); ++i)
    sum = minkowskiPair(sum, flattened(operands[i]));
  return sum;
}

SolidPtr roundedBoxShape(const std::optional<dvec3>& size, std::optional<double> r, bool center) {
  const char* function = "rounded_box";
  if (!size) throw error(function, "needs size={x, y, z} (or a number for a cube)");
  if (!r) throw error(function, "needs r (the radius of the edges)");
  for (int i = 0; i < 3; ++i) requireSide(function, "size", (*size)[i]);
  requireSide(function, "r", *r);
  double smallest = std::min({size->x, size->y, size->z});
  if (2.0 * *r > smallest) {
    std::ostringstream msg;
    msg << "r must be at most half the smallest side, " << smallest / 2.0 << " (got " << *r << ")";
    throw error(function, msg.str());
  }
  std::vector<dvec3> corners;
  for (int i = 0; i < 8; ++i) {
    dvec3 far = *size - *r;
    corners.push_back({i & 1 ? far.x : *r, i & 2 ? far.y : *r, i & 4 ? far.z : *r});
  }
  SolidPtr solid = rounded(pointHull(corners), *r, function);
  return center ? solid->transformed(Affine::translation(-0.5 * *size)) : solid;
}

SolidPtr roundedCylinderShape(std::optional<double> r, std::optional<double> h,
                              std::optional<double> fillet, bool center) {
  const char* function = "rounded_cylinder";
  if (!r || !h || !fillet) throw error(function, "needs r (radius), h (height) and fillet");
  requireSide(function, "r", *r);
  requireSide(function, "h", *h);
  requireSide(function, "fillet", *fillet);
  if (*fillet > *r || 2.0 * *fillet > *h) {
    std::ostringstream msg;
    msg << "fillet must be at most r and half of h, " << std::min(*r, *h / 2.0) << " (got "
        << *fillet << ")";
    throw error(function, msg.str());
  }
  SolidPtr solid = roundedCylinder(*r, *h, *fillet);
  return center ? solid->transformed(Affine::translation({0.0, 0.0, -0.5 * *h})) : solid;
}

}  // namespace csgray::detail
