#include "check/axis_crossings.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace csgray::detail {

AxisCrossings::AxisCrossings(const TriangleMesh& mesh, const Bounds& box, int axis, int n)
    : mesh_(mesh), axis_(axis), u_((axis + 1) % 3), v_((axis + 2) % 3), n_(n) {
  const double du = box.size()[u_] / n, dv = box.size()[v_] / n;
  // The cells a triangle's shadow box covers, clamped to the grid.
  auto cells = [&](const TriangleMesh::Triangle& t, int& i0, int& i1, int& j0, int& j1) {
    double lo[2] = {kInfinity, kInfinity}, hi[2] = {-kInfinity, -kInfinity};
    for (std::uint32_t k : t) {
      const dvec3& p = mesh.points[k];
      lo[0] = std::min(lo[0], p[u_]), hi[0] = std::max(hi[0], p[u_]);
      lo[1] = std::min(lo[1], p[v_]), hi[1] = std::max(hi[1], p[v_]);
    }
    auto cell = [n](double x) { return std::clamp(int(std::floor(x)), 0, n - 1); };
    i0 = cell((lo[0] - box.lo[u_]) / du), i1 = cell((hi[0] - box.lo[u_]) / du);
    j0 = cell((lo[1] - box.lo[v_]) / dv), j1 = cell((hi[1] - box.lo[v_]) / dv);
  };
  // Two passes: count per cell, then fill (compressed rows).
  first_.assign(std::size_t(n) * n + 1, 0);
  int i0, i1, j0, j1;
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    cells(t, i0, i1, j0, j1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) ++first_[std::size_t(i) * n + j + 1];
  }
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  triangles_.resize(first_.back());
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  for (std::uint32_t k = 0; k < mesh.triangles.size(); ++k) {
    cells(mesh.triangles[k], i0, i1, j0, j1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) triangles_[next[std::size_t(i) * n + j]++] = k;
  }
}

void AxisCrossings::crossings(const dvec3& origin, int i, int j, std::vector<Crossing>& out) const {
  out.clear();
  const std::size_t cell = std::size_t(i) * n_ + j;
  const double pu = origin[u_], pv = origin[v_];
  for (std::uint32_t c = first_[cell]; c < first_[cell + 1]; ++c) {
    const TriangleMesh::Triangle& t = mesh_.triangles[triangles_[c]];
    const dvec3& a = mesh_.points[t[0]];
    const dvec3& b = mesh_.points[t[1]];
    const dvec3& d = mesh_.points[t[2]];
    // Twice the signed areas, in the (u, v) plane, of the point with each
    // edge: all of one sign (or zero, on an edge) when the point is inside.
    auto edge = [&](const dvec3& p, const dvec3& q) {
      return (q[u_] - p[u_]) * (pv - p[v_]) - (q[v_] - p[v_]) * (pu - p[u_]);
    };
    const double wa = edge(b, d), wb = edge(d, a), wd = edge(a, b);
    const double area = wa + wb + wd;
    if (area == 0.0) continue;  // seen edge-on
    const bool inside = (wa >= 0 && wb >= 0 && wd >= 0) || (wa <= 0 && wb <= 0 && wd <= 0);
    if (!inside) continue;
    // Barycentric weights give the point's coordinate along the axis.
    const double along = (wa * a[axis_] + wb * b[axis_] + wd * d[axis_]) / area;
    dvec3 normal = glm::cross(b - a, d - a);
    normal /= glm::length(normal);
    out.push_back({along - origin[axis_], normal, triangles_[c]});
  }
  std::sort(out.begin(), out.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
}

double AxisCrossings::distance(const dvec3& p, const Crossing& c) const {
  const TriangleMesh::Triangle& t = mesh_.triangles[c.triangle];
  return pointTriangleDistance(p, mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]]);
}

}  // namespace csgray::detail
