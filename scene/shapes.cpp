#include "scene/shapes.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "primitives/blob.h"
#include "primitives/box.h"
#include "primitives/cylinder.h"
#include "primitives/half_space.h"
#include "primitives/sphere.h"
#include "primitives/superellipsoid.h"
#include "primitives/torus.h"

namespace csgray::detail {

namespace {

// Checked here rather than by the primitive, so that the message names the
// parameter the user gave.
void checkRadius(const std::string& function, const char* key, double value, bool zeroAllowed) {
  if (value > 0.0 || (zeroAllowed && value == 0.0)) return;
  std::ostringstream msg;
  msg << function << ": " << key << " must be " << (zeroAllowed ? ">= 0" : "> 0") << " (got "
      << value << ")";
  throw std::invalid_argument(msg.str());
}

// center=true moves a shape whose object frame starts at the origin so
// that its box is centred there.
SolidPtr centred(const SolidPtr& solid, bool center, const dvec3& offset) {
  return center ? solid->transformed(Affine::translation(offset)) : solid;
}

}  // namespace

std::optional<double> radiusOf(const std::string& function, const char* rKey,
                               std::optional<double> r, const char* dKey, std::optional<double> d,
                               bool zeroAllowed) {
  if (r && d)
    throw std::invalid_argument(function + ": give " + rKey + " or " + dKey + ", not both");
  if (d) {
    checkRadius(function, dKey, *d, zeroAllowed);
    return *d / 2.0;
  }
  if (r) checkRadius(function, rKey, *r, zeroAllowed);
  return r;
}

SolidPtr sphereShape(std::optional<double> r, std::optional<double> d) {
  std::optional<double> radius = radiusOf("sphere", "r", r, "d", d, false);
  if (!radius) throw std::invalid_argument("sphere: needs r (radius) or d (diameter)");
  return Primitive::create<Sphere>(*radius);
}

SolidPtr ellipsoidShape(const std::optional<dvec3>& radii) {
  if (!radii) throw std::invalid_argument("ellipsoid: needs radii={a, b, c}");
  for (int i = 0; i < 3; ++i)
    if (!((*radii)[i] > 0.0)) throw std::invalid_argument("ellipsoid: radii must be positive");
  return Primitive::create<Sphere>(1.0)->transformed(Affine::scaling(*radii));
}

SolidPtr boxShape(const std::optional<dvec3>& size, bool center) {
  if (!size) throw std::invalid_argument("box: needs size={x, y, z} (or a number for a cube)");
  return centred(Primitive::create<Box>(*size), center, -0.5 * *size);
}

SolidPtr cylinderShape(const char* function, const CylinderParams& p) {
  const std::string f = function;
  const bool defaultR2IsR1 = f == "cylinder";
  std::optional<double> r = radiusOf(f, "r", p.r, "d", p.d, false);
  std::optional<double> r1 = radiusOf(f, "r1", p.r1, "d1", p.d1, true);
  std::optional<double> r2 = radiusOf(f, "r2", p.r2, "d2", p.d2, true);
  if (!p.h) throw std::invalid_argument(f + ": needs h (height)");
  if (r && (r1 || r2)) throw std::invalid_argument(f + ": give r, or r1 and r2, not both");
  if (!r && !r1) throw std::invalid_argument(f + ": needs r or r1");
  const double bottom = r ? *r : *r1;
  const double top = r ? (defaultR2IsR1 ? *r : 0.0) : r2.value_or(defaultR2IsR1 ? bottom : 0.0);
  // Said here, in the words of the function called (cone{} too).
  if (!(std::max(bottom, top) > 0.0))
    throw std::invalid_argument(f + ": radii must be >= 0 and not both 0");
  return centred(Primitive::create<Cylinder>(bottom, top, *p.h), p.center,
                 dvec3(0.0, 0.0, -0.5 * *p.h));
}

SolidPtr halfSpaceShape(const std::optional<dvec3>& normal, double offset) {
  if (!normal) throw std::invalid_argument("half_space: needs normal={x, y, z}");
  return Primitive::create<HalfSpace>(*normal, offset);
}

SolidPtr torusShape(std::optional<double> R, std::optional<double> r) {
  if (!R || !r) throw std::invalid_argument("torus: needs R (major radius) and r (tube radius)");
  checkRadius("torus", "R", *R, true);
  checkRadius("torus", "r", *r, false);
  return Primitive::create<Torus>(*R, *r);
}

SolidPtr blobShape(std::vector<BlobBall> balls, std::optional<double> threshold) {
  return Primitive::create<Blob>(std::move(balls), threshold.value_or(kDefaultBlobThreshold));
}

SolidPtr superellipsoidShape(const std::optional<dvec3>& radii, std::optional<double> e,
                             std::optional<double> n) {
  if (!radii) throw std::invalid_argument("superellipsoid: needs radii={a, b, c} (or one number)");
  if (!e || !n)
    throw std::invalid_argument(
        "superellipsoid: needs e and n, the exponents across and along z "
        "(1 round, towards 0 square, 2 a diamond)");
  return Primitive::create<Superellipsoid>(*radii, *e, *n);
}

const char* booleanName(Boolean::Op op) {
  return op == Boolean::Op::Union          ? "union"
         : op == Boolean::Op::Intersection ? "intersection"
                                           : "difference";
}

SolidPtr booleanShape(Boolean::Op op, std::vector<SolidPtr> operands) {
  if (operands.empty())
    throw std::invalid_argument(std::string(booleanName(op)) + ": needs at least one solid");
  if (operands.size() == 1) return operands[0];
  return std::make_shared<Boolean>(op, std::move(operands));
}

std::shared_ptr<MeshSolid> meshShape(const TriangleMesh& mesh, const std::string& name) {
  // MeshSolid takes OpenSCAD's clockwise faces.
  std::vector<std::vector<std::int64_t>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[2], t[1]});
  try {
    return Primitive::create<MeshSolid>(mesh.points, faces);
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    if (message.starts_with("polyhedron: ")) message = name + ": " + message.substr(12);
    throw std::invalid_argument(message);
  }
}

}  // namespace csgray::detail
