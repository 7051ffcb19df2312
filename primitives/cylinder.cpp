#include "primitives/cylinder.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "engine/moved_box.h"
#include "engine/solvers/quadratic.h"
#include "primitives/check.h"

namespace csgray::detail {

namespace {
enum Face { kSide = 0, kBottom = 1, kTop = 2 };
}

Cylinder::Cylinder(double r1, double r2, double height)
    : r1_(r1), r2_(r2), height_(height), slope_((r2 - r1) / height) {
  requirePositive("cylinder", "h", height);
  requireFinite("cylinder", "r1", r1);
  requireFinite("cylinder", "r2", r2);
  if (r1 < 0.0 || r2 < 0.0 || !(std::max(r1, r2) > 0.0))
    throw std::invalid_argument("cylinder: radii must be >= 0 and not both 0");
}

void Cylinder::objectSpans(const Ray& ray, SpanList& out) const {
  // A ray from far away (an orthographic camera placed far off, a long
  // telephoto) makes the side's coefficients huge and nearly cancelling:
  // c = o.x² + o.y² − r² lost the radius against 6·10⁷ units, and the side
  // broke into noise. Such a ray is solved from its point nearest the
  // axis's middle, and its parameters moved back by that far.
  const dvec3 middle(0.0, 0.0, 0.5 * height_);
  const double reach = 256.0 * std::max({r1_, r2_, height_});
  double t0 = 0.0;
  if (glm::dot(ray.origin - middle, ray.origin - middle) > reach * reach)
    t0 = glm::dot(middle - ray.origin, ray.dir) / glm::dot(ray.dir, ray.dir);
  const dvec3 o = ray.origin + t0 * ray.dir;
  const dvec3& d = ray.dir;
  // Slab 0 <= z <= h.
  double zIn = -kInfinity, zOut = kInfinity;
  int capIn = kBottom, capOut = kTop;
  if (d.z == 0.0) {
    if (o.z < 0.0 || o.z > height_) return;
  } else {
    zIn = -o.z / d.z;
    zOut = (height_ - o.z) / d.z;
    if (zIn > zOut) std::swap(zIn, zOut), std::swap(capIn, capOut);
  }
  // Side: x² + y² - r(z)² <= 0 with r(z) = r1 + slope·z. Within the slab
  // r(z) >= 0, so the second nappe of the double cone never shows.
  double s0 = r1_ + slope_ * o.z, sd = slope_ * d.z;
  double a = d.x * d.x + d.y * d.y - sd * sd;
  double b = 2.0 * (o.x * d.x + o.y * d.y - s0 * sd);
  double c = o.x * o.x + o.y * o.y - s0 * s0;
  Interval side[2];
  int n = quadraticSublevel(a, b, c, side);
  for (int i = 0; i < n; ++i) {
    Boundary in = side[i].lo > zIn ? boundary(t0 + side[i].lo, kSide) : boundary(t0 + zIn, capIn);
    Boundary out_ =
        side[i].hi < zOut ? boundary(t0 + side[i].hi, kSide) : boundary(t0 + zOut, capOut);
    if (in.t > out_.t || out_.t < ray.tMin || in.t > ray.tMax) continue;
    out.push_back(in, out_);
  }
}

bool Cylinder::objectContains(const dvec3& p) const {
  if (p.z < 0.0 || p.z > height_) return false;
  double r = radiusAt(p.z);
  return p.x * p.x + p.y * p.y <= r * r;
}

dvec3 Cylinder::objectNormal(const dvec3& p, int face) const {
  if (face == kBottom) return {0.0, 0.0, -1.0};
  if (face == kTop) return {0.0, 0.0, 1.0};
  // Gradient of x² + y² - r(z)², halved.
  dvec3 n(p.x, p.y, -slope_ * radiusAt(p.z));
  if (n == dvec3(0.0)) return {0.0, 0.0, slope_ > 0.0 ? -1.0 : 1.0};  // a cone's apex
  return n;
}

Bounds Cylinder::objectBounds() const {
  double r = std::max(r1_, r2_);
  return {dvec3(-r, -r, 0.0), dvec3(r, r, height_)};
}

Bounds Cylinder::objectBoundsUnder(const Affine& worldFromObject) const {
  // A cone's frustum is the convex hull of its two end discs.
  Bounds box = movedDisc(dvec3(0.0), r1_, worldFromObject);
  box.include(movedDisc(dvec3(0.0, 0.0, height_), r2_, worldFromObject));
  return box.intersected(movedBox(objectBounds(), worldFromObject));
}

}  // namespace csgray::detail
