#include "scene/quadric_shapes.h"

#include <cmath>
#include <glm/mat4x4.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/boolean.h"
#include "primitives/box.h"
#include "primitives/quadric.h"

namespace csgray::detail {

namespace {

// 1/v² for a semi-axis v: a required positive finite number.
double inverseSquare(const char* function, const char* key, std::optional<double> v) {
  if (!v) throw std::invalid_argument(std::string(function) + ": needs " + key + " (> 0)");
  if (!(*v > 0.0)) {
    std::ostringstream msg;
    msg << function << ": " << key << " must be > 0 (got " << *v << ")";
    throw std::invalid_argument(msg.str());
  }
  // 1/v² is the entry the semi-axis contributes to the matrix. For a tiny v
  // it overflows, and for a huge one it vanishes (which would silently turn
  // the quadric into a different one): both are errors.
  double s = 1.0 / (*v * *v);
  if (!std::isfinite(s) || s == 0.0) {
    std::ostringstream msg;
    msg << function << ": " << key << " = " << *v << " is out of range (1/" << key
        << "² must be a finite non-zero double)";
    throw std::invalid_argument(msg.str());
  }
  return s;
}

glm::dmat4 diagonal(double x, double y, double z, double w) {
  glm::dmat4 m(0.0);
  m[0][0] = x;
  m[1][1] = y;
  m[2][2] = z;
  m[3][3] = w;
  return m;
}

// The matrices are those of the classic table (docs/theory.md,
// "Quadrics"; Winkler, "Raytracing", table 17.1), divided by the positive
// factor a²b²c² (a²b² for the paraboloids and the elliptic and hyperbolic
// cylinders; the parabolic cylinder's is used as it is): the same quadric
// and the same solid pᵀMp <= 0, with entries 1/a² that do not overflow for
// semi-axes where a²b²c² would. The one exception is the hyperbolic
// cylinder, whose table matrix is negated (see below).
glm::dmat4 matrixOf(NamedQuadric kind, const QuadricAxes& axes) {
  const char* f = quadricName(kind);
  if (kind == NamedQuadric::ParabolicCylinder) {
    // y² − 2px <= 0, along z: vertex line on the z axis, opening towards
    // +x for p > 0 and towards −x for p < 0. The table's matrix as it is.
    if (!axes.p) throw std::invalid_argument("parabolic_cylinder: needs p (not 0)");
    if (*axes.p == 0.0) throw std::invalid_argument("parabolic_cylinder: p must not be 0");
    glm::dmat4 m(0.0);
    m[1][1] = 1.0;
    m[0][3] = m[3][0] = -*axes.p;
    return m;
  }
  const double a2 = inverseSquare(f, "a", axes.a), b2 = inverseSquare(f, "b", axes.b);
  const double c2 = takesC(kind) ? inverseSquare(f, "c", axes.c) : 1.0;
  glm::dmat4 m(0.0);
  switch (kind) {
    case NamedQuadric::Hyperboloid1:
      // Inside the sheet, around the z axis.
      return diagonal(a2, b2, -c2, -1.0);
    case NamedQuadric::Hyperboloid2:
      // Inside both sheets, which hold the z axis for |z| >= c.
      return diagonal(a2, b2, -c2, 1.0);
    case NamedQuadric::EllipticCone:
      // Both nappes, apex at the origin.
      return diagonal(a2, b2, -c2, 0.0);
    case NamedQuadric::EllipticParaboloid:
      // Vertex at the origin, opening up +z. The linear term −z is split
      // over the two off-diagonal entries (z, w) and (w, z).
      m = diagonal(a2, b2, 0.0, 0.0);
      m[2][3] = m[3][2] = -0.5;
      return m;
    case NamedQuadric::HyperbolicParaboloid:
      // The side of the saddle above it, which holds the +z axis.
      m = diagonal(a2, -b2, 0.0, 0.0);
      m[2][3] = m[3][2] = -0.5;
      return m;
    case NamedQuadric::EllipticCylinder:
      return diagonal(a2, b2, 0.0, -1.0);
    case NamedQuadric::HyperbolicCylinder:
      // The two regions inside the sheets, which hold the x axis for
      // |x| >= a. The table's matrix, taken as it is, would give the region
      // between the sheets; the inside of the sheets is chosen to match the
      // other quadrics, whose solid is the side the surface curves around.
      // Hence the factor −1/(a²b²).
      return diagonal(-a2, b2, 0.0, 1.0);
    case NamedQuadric::ParabolicCylinder:
      break;
  }
  return m;
}

}  // namespace

const char* quadricName(NamedQuadric kind) {
  switch (kind) {
    case NamedQuadric::Hyperboloid1:
      return "hyperboloid1";
    case NamedQuadric::Hyperboloid2:
      return "hyperboloid2";
    case NamedQuadric::EllipticCone:
      return "elliptic_cone";
    case NamedQuadric::EllipticParaboloid:
      return "elliptic_paraboloid";
    case NamedQuadric::HyperbolicParaboloid:
      return "hyperbolic_paraboloid";
    case NamedQuadric::EllipticCylinder:
      return "elliptic_cylinder";
    case NamedQuadric::HyperbolicCylinder:
      return "hyperbolic_cylinder";
    case NamedQuadric::ParabolicCylinder:
      return "parabolic_cylinder";
  }
  return "quadric";
}

bool takesC(NamedQuadric kind) {
  return kind == NamedQuadric::Hyperboloid1 || kind == NamedQuadric::Hyperboloid2 ||
         kind == NamedQuadric::EllipticCone;
}

bool takesP(NamedQuadric kind) { return kind == NamedQuadric::ParabolicCylinder; }

SolidPtr namedQuadricShape(NamedQuadric kind, const QuadricAxes& axes) {
  return Primitive::create<Quadric>(matrixOf(kind, axes));
}

SolidPtr clipBoxShape(const std::optional<dvec3>& lo, const std::optional<dvec3>& hi) {
  if (!lo || !hi) throw std::invalid_argument(std::string("clip: needs ") + (lo ? "hi" : "lo"));
  const char* axes = "xyz";
  for (int i = 0; i < 3; ++i) {
    if (!((*lo)[i] < (*hi)[i])) {
      std::ostringstream msg;
      msg << "clip: lo must be below hi on every axis (" << axes[i] << ": " << (*lo)[i]
          << " >= " << (*hi)[i] << ")";
      throw std::invalid_argument(msg.str());
    }
    if (!std::isfinite((*hi)[i] - (*lo)[i]))
      throw std::invalid_argument(std::string("clip: the box is too large along ") + axes[i]);
  }
  return Primitive::create<Box>(*hi - *lo)->transformed(Affine::translation(*lo));
}

MaterialPtr uniformMaterial(const Solid& solid) {
  MaterialPtr found;
  bool first = true;
  std::vector<const Solid*> pending{&solid};  // a walk without recursion: trees may be deep
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    if (const auto* p = dynamic_cast<const Primitive*>(s)) {
      if (!first && p->material() != found) return nullptr;
      found = p->material();
      first = false;
    }
    for (const SolidPtr& child : s->children()) pending.push_back(child.get());
  }
  return found;
}

SolidPtr clippedShape(const SolidPtr& solid, std::vector<SolidPtr> cutters) {
  if (cutters.empty()) throw std::invalid_argument("clip: needs a box {lo=, hi=} or solids");
  if (MaterialPtr material = uniformMaterial(*solid))
    for (SolidPtr& c : cutters) c = c->withDefaultMaterial(material);
  std::vector<SolidPtr> operands{solid};
  operands.insert(operands.end(), cutters.begin(), cutters.end());
  return std::make_shared<Boolean>(Boolean::Op::Intersection, std::move(operands));
}

}  // namespace csgray::detail
