#include "openscad/openscad_sweeps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "engine/degrees.h"
#include "openscad/csg_import.h"
#include "scene/shapes.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
// OpenSCAD's GRID_FINE: a radius below it counts as none.
constexpr double kGridFine = 0.00000095367431640625;

double largestRadiusSquared(const SweepLoops& loops) {
  double r2 = 0.0;
  for (const auto& loop : loops)
    for (const dvec2& u : loop) r2 = std::max(r2, glm::dot(u, u));
  return r2;
}

// OpenSCAD's get_helix_slices: a helix of radius r turned by `twist`
// degrees over `height` is L = T·√(r² + c²) long (T the twist in radians,
// c = height / T; https://mathworld.wolfram.com/Helix.html), cut into
// steps of $fs or of $fa degrees, whichever is fewer.
int helixSlices(double r2, double height, double twist, const OpenScadResolution& res, int least) {
  if (res.fn > 0.0) return std::max(int(std::ceil(twist / 360.0 * res.fn)), least);
  const double t = twist * kRadiansPerDegree, c = height / t;
  const double length = t * std::sqrt(r2 + c * c);
  const int byAngle = int(std::ceil(twist / res.fa)), byLength = int(std::ceil(length / res.fs));
  return std::max(std::min(byAngle, byLength), least);
}

// Twice the arc length of Archimedes' spiral r = a·θ from 0 to θ
// (https://mathworld.wolfram.com/ArchimedesSpiral.html), halved.
double spiralLength(double a, double theta) {
  return 0.5 * a * (theta * std::sqrt(1.0 + theta * theta) + std::asinh(theta));
}

// OpenSCAD's get_conical_helix_slices: under a uniform scale s a point
// moves on a conical helix, whose plan is a piece of Archimedes' spiral
// between the angles where the spiral's radius is r·min(1, s) and
// r·max(1, s) (the spiral reaching the axis where the scale would reach
// 0); its length with the height as the other side of a right triangle.
int conicalHelixSlices(double r2, double height, double twist, double scale,
                       const OpenScadResolution& res, int least) {
  if (res.fn > 0.0) return std::max(int(std::ceil(twist * res.fn / 360.0)), least);
  const double t = twist * kRadiansPerDegree;
  const double end = scale > 1.0 ? t * scale / (scale - 1.0) : t / (1.0 - scale);
  const double a = std::sqrt(r2) / end;
  const double spiral = spiralLength(a, end) - spiralLength(a, end - t);
  const double length = std::sqrt(spiral * spiral + height * height);
  const int byAngle = int(std::ceil(twist / res.fa)), byLength = int(std::ceil(length / res.fs));
  return std::max(std::min(byAngle, byLength), least);
}

// OpenSCAD's get_diagonal_slices: a point moves by at most √δ² in the
// plane while rising by the height; $fn slices, or steps of $fs.
int diagonalSlices(double delta2, double height, const OpenScadResolution& res) {
  if (std::sqrt(delta2) < kGridFine) return 1;
  if (res.fn > 0.0) return std::max(int(res.fn), 1);
  return std::max(int(std::ceil(std::sqrt(delta2 + height * height) / res.fs)), 1);
}

std::size_t pointCount(const SweepLoops& loops) {
  std::size_t n = 0;
  for (const auto& loop : loops) n += loop.size();
  return n;
}

// OpenSCAD's sgn_vdiff: which of two diagonals is shorter, −1 for the
// first, 1 for the second, 0 when they differ by less than 10 ppm of
// their mean (so that the choice does not hang on rounding).
int shorter(const dvec2& first, const dvec2& second) {
  const double l1 = glm::length(first), l2 = glm::length(second);
  return 2.0 * std::abs(l1 - l2) * 1e5 > l1 + l2 ? (l1 < l2 ? -1 : 1) : 0;
}

}  // namespace

void requireOpenScadTriangles(double triangles) {
  if (triangles > double(kMaxTessellationTriangles))
    throw std::invalid_argument("OpenSCAD's polygons would take " +
                                std::to_string(std::llround(triangles)) + " triangles, more than " +
                                std::to_string(kMaxTessellationTriangles));
}

int openscadExtrudeSlices(const SweepLoops& loops, const OpenScadLinearExtrude& e,
                          const OpenScadResolution& res) {
  if (e.slices) return *e.slices;
  const bool uniform = e.scale.x == e.scale.y;
  if (e.twistDegrees != 0.0) {
    const double twist = std::abs(e.twistDegrees);
    // At least 3 slices a turn: 180° a slice could not be a solid.
    const int least = std::max(int(std::ceil(twist / 120.0)), 1);
    const double r2 = largestRadiusSquared(loops);
    if (std::sqrt(r2) < kGridFine || !std::isfinite(res.fn)) return least;
    // OpenSCAD takes the straight helix also for a scale per axis.
    if (!uniform || e.scale.x == 1.0) return helixSlices(r2, e.height, twist, res, least);
    return conicalHelixSlices(r2, e.height, twist, e.scale.x, res, least);
  }
  if (!uniform) {
    double delta2 = 0.0;
    for (const auto& loop : loops)
      for (const dvec2& u : loop) {
        const dvec2 d = u - u * e.scale;
        delta2 = std::max(delta2, glm::dot(d, d));
      }
    return diagonalSlices(delta2, e.height, res);
  }
  return 1;
}

SolidPtr openscadLinearExtrusion(const SweepLoops& loops, const OpenScadLinearExtrude& e,
                                 const OpenScadResolution& res) {
  const bool apex = e.scale.x == 0.0 && e.scale.y == 0.0;
  if (!apex && (e.scale.x == 0.0 || e.scale.y == 0.0))
    throw std::invalid_argument(
        "a scale of 0 on one axis flattens the top to a segment, which OpenSCAD's polygons "
        "cannot close");
  const int slices = openscadExtrudeSlices(loops, e, res);
  requireOpenScadTriangles(2.0 * double(pointCount(loops)) * (slices + 1));
  const double z0 = e.center ? -0.5 * e.height : 0.0;

  TriangleMesh mesh;
  SweepLevels levels(slices + 1);
  // plane[k][l][i]: levels[k][l][i]'s point in the plane, for the diagonals.
  std::vector<std::vector<std::vector<dvec2>>> plane(slices + 1);
  for (int k = 0; k <= slices; ++k) {
    // Level k: the loops turned by −twist·k/N, then scaled by
    // 1 − (1 − s)·k/N on each axis, at the height k/N up.
    const double f = double(k) / slices;
    const dvec2 sigma = dvec2(1.0) - (dvec2(1.0) - e.scale) * f;
    const dvec2 turn = unitCircleDegrees(-e.twistDegrees * f);
    const double c = turn.x, s = turn.y;
    const double z = k == slices ? z0 + e.height : z0 + e.height * f;
    const bool top = apex && k == slices;  // one point
    if (top) mesh.points.emplace_back(0.0, 0.0, z);
    levels[k].resize(loops.size());
    plane[k].resize(loops.size());
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (const dvec2& u : loops[l]) {
        const dvec2 p = top ? dvec2(0.0) : sigma * dvec2(c * u.x - s * u.y, s * u.x + c * u.y);
        if (!top) mesh.points.emplace_back(p, z);
        levels[k][l].push_back(std::uint32_t(mesh.points.size() - 1));
        plane[k][l].push_back(p);
      }
  }
  // OpenSCAD cuts each side quad along its shorter diagonal in the plane;
  // where they are as long, an outer loop's quads along the one from the
  // corner below to the next above when the twist is positive, a hole's
  // the other way. (Below an apex either way makes the one triangle.)
  std::vector<bool> outer(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) outer[l] = signedArea2(loops[l]) > 0.0;
  const bool positiveTwist = e.twistDegrees > 0.0;
  addSweepFaces(mesh, loops, levels, false, false, [&](int k, std::size_t l, std::size_t i) {
    const std::size_t j = (i + 1) % loops[l].size();
    const dvec2 &a = plane[k][l][i], &b = plane[k][l][j];
    const dvec2 &c = plane[k + 1][l][j], &d = plane[k + 1][l][i];
    const int sign = shorter(a - c, b - d);
    return !(sign == -1 || (sign == 0 && outer[l] == positiveTwist));
  });
  return meshShape(mesh, "linear_extrude");
}

int openscadRevolutionSteps(double reach, double angleDegrees, const OpenScadResolution& res) {
  const int fragments = openscadFragments(reach, res.fn, res.fa, res.fs);
  return int(std::max(fragments * std::abs(angleDegrees) / 360.0, 1.0));
}

SolidPtr openscadRevolution(const SweepLoops& loops, double angleDegrees,
                            const OpenScadResolution& res) {
  double reach = 0.0;
  for (const auto& loop : loops)
    for (const dvec2& u : loop) reach = std::max(reach, u.x);
  const int steps = openscadRevolutionSteps(reach, angleDegrees, res);
  requireOpenScadTriangles(2.0 * double(pointCount(loops)) * (steps + 1));
  return meshShape(revolvedLoops(loops, angleDegrees, steps, angleDegrees >= 360.0),
                   "rotate_extrude");
}

}  // namespace csgray::detail
