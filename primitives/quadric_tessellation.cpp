// Quadric::objectTessellate: a closed mesh of a quadric solid within a
// region (its exact part is quadric.cpp).
//
// In the canonical frame of quadric_form.h the solid is one of a few shapes:
// - a loft of ellipses λ₀y₀² + λ₁y₁² <= ρ(y₂) along y₂ (ellipsoid, elliptic
//   cylinder and paraboloid, hyperboloids, one nappe of a cone);
// - a prism between two graphs over a rectangle: y_w between lower(y_u, y_v)
//   and upper(y_u, y_v), where each graph is flat or the sum of an even
//   function of y_u and one of y_v (the other paraboloids, the parabolic and
//   hyperbolic cylinders, slabs, half-spaces, the whole space).
// Both are built in canonical coordinates and then placed in the object
// frame. Artificial faces (caps, walls, flat sides) lie on the region's box
// in the canonical frame grown by a margin, or beyond it where a graph leaves
// that box (a graph is never clipped: the box is extended past it instead).
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/solvers/quadric_form.h"
#include "primitives/quadric.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

const char* const kKind = "quadric";

// The margin around the region, as a fraction of its diagonal: the mesh's own
// caps must not coincide with the faces of the box or half-spaces that the
// caller later intersects it with.
constexpr double kMarginFraction = 0.02;

// A function of one canonical coordinate that is even and monotone on each
// side of 0, and convex or concave on the ranges it is sampled over:
// k·x², k·|x| or ±√(αx² + β). An empty one is 0.
using Profile = std::function<double(double)>;

double profileAt(const Profile& f, double x) { return f ? f(x) : 0.0; }

// The least and largest value of such a profile over [a, b].
std::pair<double, double> profileRange(const Profile& f, double a, double b) {
  if (!f) return {0.0, 0.0};
  double lo = std::min(f(a), f(b)), hi = std::max(f(a), f(b));
  if (a < 0.0 && b > 0.0) {
    lo = std::min(lo, f(0.0));
    hi = std::max(hi, f(0.0));
  }
  return {lo, hi};
}

// Samples a = x₀ < x₁ < ... = b such that every profile's chord between
// neighbours stays within tolerance/2 of it. On a convex (or concave)
// stretch the gap between chord and curve is a concave function that
// vanishes at the ends, so its largest value is at most twice its value at
// the middle: that middle gap is kept below tolerance/4.
std::vector<double> chordSamples(double a, double b, const std::vector<const Profile*>& profiles,
                                 double tolerance, double trianglesPerSample) {
  const double limit = double(kMaxTessellationTriangles) / trianglesPerSample + 2.0;
  std::vector<double> out{a};
  std::vector<std::pair<double, double>> pending{{a, b}};
  while (!pending.empty()) {
    const auto [x0, x1] = pending.back();
    pending.pop_back();
    const double mid = 0.5 * (x0 + x1);
    bool split = false;
    if (mid > x0 && mid < x1) {
      for (const Profile* f : profiles) {
        if (*f && std::abs((*f)(mid)-0.5 * ((*f)(x0) + (*f)(x1))) > 0.25 * tolerance) split = true;
      }
    }
    if (split) {
      pending.emplace_back(mid, x1);
      pending.emplace_back(x0, mid);
    } else {
      out.push_back(x1);
      if (double(out.size()) > limit)
        requireTriangleBudget(kKind, double(out.size()) * trianglesPerSample, tolerance);
    }
  }
  return out;
}

TriangleMesh::Triangle triangle(std::size_t a, std::size_t b, std::size_t c) {
  return {std::uint32_t(a), std::uint32_t(b), std::uint32_t(c)};
}

// The loft of ellipses λ₀y₀² + λ₁y₁² <= ρ(t) at y₂ = t over [ta, tb], with
// ρ >= 0 there (ρ a polynomial of degree <= 2, so √ρ is convex or concave on
// the range). An end where ρ = 0 is a pole (a single vertex), any other end
// a flat cap. Outward for right-handed canonical axes.
TriangleMesh ellipseLoft(double lambda0, double lambda1, const std::function<double(double)>& rho,
                         double ta, double tb, bool poleA, bool poleB, double tolerance) {
  const double least = std::min(lambda0, lambda1);
  double maxRho = std::max(rho(ta), rho(tb));
  if (ta < 0.0 && tb > 0.0) maxRho = std::max(maxRho, rho(0.0));
  // Uniform angles on an ellipse: it is a circle of its larger semi-axis
  // squeezed along one axis, a contraction, so the circle's chord error
  // bounds the ellipse's.
  const int segments =
      arcSegments(std::sqrt(maxRho / least), 2.0 * std::numbers::pi, 0.5 * tolerance);
  requireTriangleBudget(kKind, 2.0 * segments, tolerance);
  const Profile radius = [&](double t) { return std::sqrt(std::max(rho(t), 0.0) / least); };
  const std::vector<double> ts = chordSamples(ta, tb, {&radius}, tolerance, 2.0 * segments);

  TriangleMesh mesh;
  std::vector<std::size_t> ringStart;  // first vertex of each ring; a pole has one
  const std::size_t last = ts.size() - 1;
  auto isPole = [&](std::size_t i) { return (i == 0 && poleA) || (i == last && poleB); };
  for (std::size_t i = 0; i < ts.size(); ++i) {
    ringStart.push_back(mesh.points.size());
    if (isPole(i)) {
      mesh.points.emplace_back(0.0, 0.0, ts[i]);
      continue;
    }
    const double r = std::max(rho(ts[i]), 0.0);
    const double a0 = std::sqrt(r / lambda0), a1 = std::sqrt(r / lambda1);
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / segments;
      mesh.points.emplace_back(a0 * std::cos(angle), a1 * std::sin(angle), ts[i]);
    }
  }
  auto at = [&](std::size_t i, int k) { return ringStart[i] + std::size_t(k % segments); };
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const bool lowPole = isPole(i), highPole = isPole(i + 1);
    for (int k = 0; k < segments; ++k) {
      if (lowPole) {
        mesh.triangles.push_back(triangle(ringStart[i], at(i + 1, k + 1), at(i + 1, k)));
      } else if (highPole) {
        mesh.triangles.push_back(triangle(at(i, k), at(i, k + 1), ringStart[i + 1]));
      } else {
        mesh.triangles.push_back(triangle(at(i, k), at(i, k + 1), at(i + 1, k + 1)));
        mesh.triangles.push_back(triangle(at(i, k), at(i + 1, k + 1), at(i + 1, k)));
      }
    }
  }
  // Flat caps: fans from a centre vertex.
  if (!isPole(0)) {
    const std::size_t centre = mesh.points.size();
    mesh.points.emplace_back(0.0, 0.0, ta);
    for (int k = 0; k < segments; ++k)
      mesh.triangles.push_back(triangle(centre, at(0, k + 1), at(0, k)));
  }
  if (!isPole(last)) {
    const std::size_t centre = mesh.points.size();
    mesh.points.emplace_back(0.0, 0.0, tb);
    for (int k = 0; k < segments; ++k)
      mesh.triangles.push_back(triangle(centre, at(last, k), at(last, k + 1)));
  }
  return mesh;
}

// The graph y_w = c + fu(y_u) + fv(y_v).
struct Graph {
  double c = 0.0;
  Profile fu, fv;

  bool flat() const { return !fu && !fv; }
  double at(double u, double v) const { return c + profileAt(fu, u) + profileAt(fv, v); }
};

// The axes and the rectangle of a prism in canonical coordinates.
struct PrismFrame {
  int u, v, w;  // which canonical axis each is
  double u0, u1, v0, v1;
};

// The solid lower(u, v) <= y_w <= upper(u, v) over the rectangle, with
// lower < upper everywhere. A sum of functions of u and of v is interpolated
// on the grid's triangles exactly as each function is along its own axis,
// so the errors of the two chord samplings add up to at most the tolerance.
// Outward when (u, v, w) is a right-handed order of the axes.
TriangleMesh graphPrism(const PrismFrame& f, const Graph& lower, const Graph& upper,
                        double tolerance) {
  const int nonFlat = !lower.flat() + !upper.flat();
  const std::vector<double> us =
      chordSamples(f.u0, f.u1, {&lower.fu, &upper.fu}, tolerance, 2.0 * std::max(nonFlat, 1));
  const double perV = 2.0 * std::max(nonFlat, 1) * double(us.size());
  const std::vector<double> vs = chordSamples(f.v0, f.v1, {&lower.fv, &upper.fv}, tolerance, perV);
  const std::size_t nu = us.size(), nv = vs.size();
  requireTriangleBudget(kKind, 2.0 * nonFlat * double(nu) * double(nv) + 4.0 * double(nu + nv),
                        tolerance);

  TriangleMesh mesh;
  auto addPoint = [&](double u, double v, double w) {
    dvec3 y;
    y[f.u] = u;
    y[f.v] = v;
    y[f.w] = w;
    mesh.points.push_back(y);
    return mesh.points.size() - 1;
  };
  // The boundary of the grid, counter-clockwise seen from +w.
  std::vector<std::pair<std::size_t, std::size_t>> loop;
  for (std::size_t i = 0; i + 1 < nu; ++i) loop.emplace_back(i, 0);
  for (std::size_t j = 0; j + 1 < nv; ++j) loop.emplace_back(nu - 1, j);
  for (std::size_t i = nu - 1; i > 0; --i) loop.emplace_back(i, nv - 1);
  for (std::size_t j = nv - 1; j > 0; --j) loop.emplace_back(0, j);

  // One side (lower or upper): a grid, or for a flat graph a fan from the
  // rectangle's centre to the boundary. Returns the boundary's vertices.
  auto addSide = [&](const Graph& g, bool up) {
    std::vector<std::size_t> boundary;
    if (g.flat()) {
      for (const auto& [i, j] : loop) boundary.push_back(addPoint(us[i], vs[j], g.c));
      const std::size_t centre = addPoint(0.5 * (f.u0 + f.u1), 0.5 * (f.v0 + f.v1), g.c);
      for (std::size_t k = 0; k < boundary.size(); ++k) {
        const std::size_t a = boundary[k], b = boundary[(k + 1) % boundary.size()];
        mesh.triangles.push_back(up ? triangle(centre, a, b) : triangle(centre, b, a));
      }
      return boundary;
    }
    const std::size_t first = mesh.points.size();
    for (std::size_t i = 0; i < nu; ++i)
      for (std::size_t j = 0; j < nv; ++j) addPoint(us[i], vs[j], g.at(us[i], vs[j]));
    auto at = [&](std::size_t i, std::size_t j) { return first + i * nv + j; };
    for (std::size_t i = 0; i + 1 < nu; ++i) {
      for (std::size_t j = 0; j + 1 < nv; ++j) {
        const std::size_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        if (up) {
          mesh.triangles.push_back(triangle(a, b, c));
          mesh.triangles.push_back(triangle(a, c, d));
        } else {
          mesh.triangles.push_back(triangle(a, c, b));
          mesh.triangles.push_back(triangle(a, d, c));
        }
      }
    }
    for (const auto& [i, j] : loop) boundary.push_back(at(i, j));
    return boundary;
  };
  const std::vector<std::size_t> low = addSide(lower, false), high = addSide(upper, true);
  // The walls: quads between the two boundaries, facing out of the loop.
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const std::size_t n = (k + 1) % loop.size();
    mesh.triangles.push_back(triangle(low[k], low[n], high[n]));
    mesh.triangles.push_back(triangle(low[k], high[n], high[k]));
  }
  return mesh;
}

// Builds the shells of the solid in canonical coordinates and collects them
// in the object frame.
class QuadricMesher {
 public:
  QuadricMesher(const QuadricForm& form, double tolerance, const Bounds& region)
      : form_(form), tolerance_(tolerance), region_(region) {}

  TriangleMesh run();

 private:
  // The region's box in the canonical frame (inner) and grown by the margin
  // (outer); unbounded shapes call this first.
  void requireRegion() {
    if (!region_.finite())
      throw std::invalid_argument(
          "quadric: is unbounded; clip it with a box or half-spaces to export it");
    for (int i = 0; i < 8; ++i) {
      const dvec3 corner(i & 1 ? region_.hi.x : region_.lo.x, i & 2 ? region_.hi.y : region_.lo.y,
                         i & 4 ? region_.hi.z : region_.lo.z);
      inner_.include(form_.toCanonical(corner));
    }
    margin_ = kMarginFraction * glm::length(inner_.size());
    if (!(margin_ > 0.0)) margin_ = 1.0;
    outer_ = {inner_.lo - dvec3(margin_), inner_.hi + dvec3(margin_)};
  }

  // A shell in canonical coordinates, placed and turned outward.
  void add(TriangleMesh shell) {
    for (dvec3& p : shell.points) p = form_.toObject(p);
    if (shell.volume() < 0.0) shell.flip();
    mesh_.append(shell);
  }

  void loft(const std::function<double(double)>& rho, double ta, double tb, bool poleA,
            bool poleB) {
    if (ta < tb)
      add(ellipseLoft(form_.lambda[0], form_.lambda[1], rho, ta, tb, poleA, poleB, tolerance_));
  }

  PrismFrame prismFrame(int w) const {
    const int u = (w + 1) % 3, v = (w + 2) % 3;
    return {u, v, w, outer_.lo[u], outer_.hi[u], outer_.lo[v], outer_.hi[v]};
  }

  // The solid between two flat faces across axis w, within the outer box.
  void slab(int w, double lo, double hi) {
    lo = std::max(lo, outer_.lo[w]);
    hi = std::min(hi, outer_.hi[w]);
    if (lo < hi) add(graphPrism(prismFrame(w), Graph{lo, {}, {}}, Graph{hi, {}, {}}, tolerance_));
  }

  // The solid y_w >= g (above) or y_w <= g over the outer box's rectangle
  // across w. A flat g is clipped to the box; a curved one is not, and the
  // flat far side moves past it instead.
  void graphSide(int w, const Graph& g, bool above) {
    if (g.flat()) {
      if (above)
        slab(w, g.c, kInfinity);
      else
        slab(w, -kInfinity, g.c);
      return;
    }
    const PrismFrame f = prismFrame(w);
    const auto [uLo, uHi] = profileRange(g.fu, f.u0, f.u1);
    const auto [vLo, vHi] = profileRange(g.fv, f.v0, f.v1);
    const double least = g.c + uLo + vLo, most = g.c + uHi + vHi;
    if (above) {
      if (least >= outer_.hi[w]) return;  // no part of the solid in the box
      add(graphPrism(f, g, Graph{std::max(outer_.hi[w], most + margin_), {}, {}}, tolerance_));
    } else {
      if (most <= outer_.lo[w]) return;
      add(graphPrism(f, Graph{std::min(outer_.lo[w], least - margin_), {}, {}}, g, tolerance_));
    }
  }

  void paraboloid();
  void hyperbolicCylinder(int negative, int positive);
  void threeAxes();

  QuadricForm form_;
  double tolerance_;
  Bounds region_;
  Bounds inner_, outer_;
  double margin_ = 0.0;
  TriangleMesh mesh_;
};

const char* const kOutsideMessage =
    "quadric: the outside of an ellipsoid, elliptic cylinder, hyperboloid or cone cannot be "
    "tessellated; subtract the inside from a box instead";

// λ₀y₀² + λ₁y₁² + 2b·y₂ <= 0 with b > 0.
void QuadricMesher::paraboloid() {
  const dvec3& l = form_.lambda;
  const double b = form_.linear;
  requireRegion();
  if (l[0] > 0.0 && l[1] > 0.0) {
    // An elliptic paraboloid opening towards −y₂: ellipses with ρ = −2b·t.
    const double tb = std::min(0.0, outer_.hi.z);
    loft([b](double t) { return -2.0 * b * t; }, outer_.lo.z, tb, false, tb == 0.0);
    return;
  }
  // y₂ <= −(λ₀y₀² + λ₁y₁²)/(2b): hyperbolic paraboloid, parabolic cylinder,
  // the outside of an elliptic paraboloid, a half-space.
  Graph g;
  if (l[0] != 0.0) g.fu = [k = -l[0] / (2.0 * b)](double u) { return k * u * u; };
  if (l[1] != 0.0) g.fv = [k = -l[1] / (2.0 * b)](double v) { return k * v * v; };
  // The prism's (u, v, w) = (y₀, y₁, y₂).
  graphSide(2, g, false);
}

// λ_n·y_n² + λ_p·y_p² + d <= 0 with λ_n < 0 < λ_p, along y₂.
void QuadricMesher::hyperbolicCylinder(int n, int p) {
  const double ln = -form_.lambda[n], lp = form_.lambda[p], d = form_.constant;
  requireRegion();
  // prismFrame(w) takes u = w+1, v = w+2 (mod 3): the profile goes on
  // whichever of u, v is the other section axis, not y₂.
  auto onOther = [](Graph& g, int w, int other, Profile f) {
    ((w + 1) % 3 == other ? g.fu : g.fv) = std::move(f);
  };
  if (d > 0.0) {
    // |y_n| >= √((λ_p·y_p² + d)/λ_n): the two regions inside the sheets.
    const Profile g = [=](double x) { return std::sqrt((lp * x * x + d) / ln); };
    Graph outer, inner;
    onOther(outer, n, p, g);
    onOther(inner, n, p, [g](double x) { return -g(x); });
    graphSide(n, outer, true);
    graphSide(n, inner, false);
  } else if (d < 0.0) {
    // |y_p| <= √((λ_n·y_n² − d)/λ_p): the region between the sheets.
    const Profile g = [=](double x) { return std::sqrt((ln * x * x - d) / lp); };
    const PrismFrame f = prismFrame(p);
    const double most = profileRange(g, outer_.lo[n], outer_.hi[n]).second;
    if (most <= outer_.lo[p] || -most >= outer_.hi[p]) return;
    Graph lower, upper;
    onOther(upper, p, n, g);
    onOther(lower, p, n, [g](double x) { return -g(x); });
    add(graphPrism(f, lower, upper, tolerance_));
  } else {
    // Two planes |y_p| <= k|y_n| crossing on the y₂ axis: a wedge on each
    // side, which touch along that line.
    if (inner_.lo[n] <= 0.0 && inner_.hi[n] >= 0.0)
      throw std::invalid_argument(
          "quadric: its two planes cross inside the region, where the solid is not a "
          "2-manifold; clip it to one side of the line where they cross");
    const double k = std::sqrt(ln / lp);
    const Profile g = [k](double x) { return k * std::abs(x); };
    PrismFrame f = prismFrame(p);
    // Keep the wedge's thin end off the crossing line, still outside the region.
    double& near =
        (p + 1) % 3 == n ? (inner_.lo[n] > 0.0 ? f.u0 : f.u1) : (inner_.lo[n] > 0.0 ? f.v0 : f.v1);
    near = inner_.lo[n] > 0.0 ? std::max(near, 0.5 * inner_.lo[n])
                              : std::min(near, 0.5 * inner_.hi[n]);
    Graph lower, upper;
    onOther(upper, p, n, g);
    onOther(lower, p, n, [g](double x) { return -g(x); });
    add(graphPrism(f, lower, upper, tolerance_));
  }
}

// Three non-zero λ; y₂'s sign differs from the others' unless all agree.
void QuadricMesher::threeAxes() {
  const dvec3& l = form_.lambda;
  const double d = form_.constant;
  if (l[0] < 0.0 && l[1] < 0.0) {
    // −(|λ₀|y₀² + |λ₁|y₁²) + λ₂y₂² + d <= 0 for λ₂ of either sign: the whole
    // space when every term can be <= 0 everywhere, else an outside.
    if (l[2] < 0.0 && d <= 0.0) {
      requireRegion();
      slab(2, -kInfinity, kInfinity);
      return;
    }
    throw std::invalid_argument(kOutsideMessage);
  }
  const auto rho = [l2 = l[2], d](double t) { return -(l2 * t * t + d); };
  if (l[2] > 0.0) {
    // An ellipsoid (bounded: the region does not matter), or nothing.
    if (d >= 0.0) return;
    const double t = std::sqrt(-d / l[2]);
    loft(rho, -t, t, true, true);
    return;
  }
  requireRegion();
  const double ta = outer_.lo.z, tb = outer_.hi.z;
  if (d < 0.0) {
    loft(rho, ta, tb, false, false);  // hyperboloid of one sheet
  } else if (d > 0.0) {
    // Hyperboloid of two sheets, vertices at ±tv.
    const double tv = std::sqrt(d / -l[2]);
    loft(rho, ta, std::min(tb, -tv), false, -tv <= tb);
    loft(rho, std::max(ta, tv), tb, tv >= ta, false);
  } else {
    // A double cone, apex at the origin: one nappe at a time.
    if (inner_.lo.z < 0.0 && inner_.hi.z > 0.0)
      throw std::invalid_argument(
          "quadric: the cone's apex lies inside the region, where its two nappes meet in a "
          "point (not a 2-manifold); clip it to one nappe");
    if (inner_.hi.z <= 0.0)
      loft(rho, ta, std::min(tb, 0.0), false, tb >= 0.0);
    else
      loft(rho, std::max(ta, 0.0), tb, ta <= 0.0, false);
  }
}

TriangleMesh QuadricMesher::run() {
  const dvec3& l = form_.lambda;
  const double d = form_.constant;
  if (form_.linear > 0.0) {
    paraboloid();
    return std::move(mesh_);
  }
  int positive = 0, negative = 0;
  for (int i = 0; i < 3; ++i) {
    positive += l[i] > 0.0;
    negative += l[i] < 0.0;
  }
  if (positive + negative == 3) {
    threeAxes();
  } else if (positive + negative == 0) {
    // The constant form d <= 0: everything or nothing.
    if (d > 0.0) return {};
    requireRegion();
    slab(2, -kInfinity, kInfinity);
  } else if (negative == 0) {
    // λ >= 0 and d: an elliptic cylinder, a slab, or nothing (also for
    // d = 0: a line or a plane has no volume).
    if (d >= 0.0) return {};
    requireRegion();
    if (positive == 2)
      loft([d](double) { return -d; }, outer_.lo.z, outer_.hi.z, false, false);
    else
      slab(0, -std::sqrt(-d / l[0]), std::sqrt(-d / l[0]));
  } else if (positive == 0) {
    // λ <= 0: everything, the two half-spaces outside a slab, or the outside
    // of an elliptic cylinder.
    if (d <= 0.0) {
      requireRegion();
      slab(2, -kInfinity, kInfinity);
    } else if (negative == 1) {
      requireRegion();
      const double s = std::sqrt(d / -l[0]);
      slab(0, s, kInfinity);
      slab(0, -kInfinity, -s);
    } else {
      throw std::invalid_argument(kOutsideMessage);
    }
  } else {
    hyperbolicCylinder(l[0] < 0.0 ? 0 : 1, l[0] < 0.0 ? 1 : 0);
  }
  return std::move(mesh_);
}

}  // namespace

TriangleMesh Quadric::objectTessellate(double tolerance, const Bounds& region) const {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("quadric: the tolerance must be a positive number");
  return QuadricMesher(canonicalQuadricForm(m_), tolerance, region).run();
}

}  // namespace csgray::detail
