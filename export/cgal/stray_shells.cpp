#include "export/cgal/stray_shells.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <unordered_map>
#include <vector>

#include "tessellation/mesh_shells.h"

namespace csgray::detail {

namespace {

// How many of a shell's largest faces are probed, and how many probes must
// give an answer for the shell to be removed.
constexpr std::size_t kProbes = 5;
constexpr std::size_t kAnswers = 2;

// Where the ray from `origin` along `dir` first crosses one of the faces,
// not `skip`, ahead of it (Möller and Trumbore, "Fast, minimum storage
// ray-triangle intersection", 1997); infinity if it crosses none.
double firstCrossing(const TriangleMesh& mesh, const std::vector<std::uint32_t>& faces,
                     std::uint32_t skip, const dvec3& origin, const dvec3& dir) {
  double nearest = kInfinity;
  for (std::uint32_t f : faces) {
    if (f == skip) continue;
    const auto& t = mesh.triangles[f];
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) continue;
    const dvec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double distance = glm::dot(e2, q) / det;
    if (distance > 0.0) nearest = std::min(nearest, distance);
  }
  return nearest;
}

}  // namespace

std::size_t removeStrayShells(PartMesh& part, const Solid& solid, double tolerance) {
  const TriangleMesh& mesh = part.mesh;
  const MeshShells shells = meshShells(mesh);
  if (shells.count < 2) return 0;
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> facesOf;
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
    facesOf[shells.shellOfPoint[mesh.triangles[f][0]]].push_back(f);

  auto area = [&](std::uint32_t f) {
    const auto& t = mesh.triangles[f];
    return glm::length(
        glm::cross(mesh.points[t[1]] - mesh.points[t[0]], mesh.points[t[2]] - mesh.points[t[0]]));
  };
  std::vector<std::uint32_t> allFaces(mesh.triangles.size());
  for (std::uint32_t f = 0; f < allFaces.size(); ++f) allFaces[f] = f;
  std::vector<bool> stray(mesh.triangles.size(), false);
  std::size_t removed = 0;
  for (auto& [shell, faces] : facesOf) {
    // Only thin shells: volume (divergence theorem) at most the tolerance
    // times the area, about half their thickness. Cavities (negative
    // volume) are kept.
    double volume = 0.0, surface = 0.0;
    for (std::uint32_t f : faces) {
      const auto& t = mesh.triangles[f];
      volume += glm::dot(mesh.points[t[0]], glm::cross(mesh.points[t[1]], mesh.points[t[2]])) / 6.0;
      surface += 0.5 * area(f);
    }
    if (!(volume > 0.0) || volume > tolerance * surface) continue;
    std::vector<std::uint32_t> largest = faces;
    const std::size_t probes = std::min(kProbes, largest.size());
    std::partial_sort(largest.begin(), largest.begin() + std::ptrdiff_t(probes), largest.end(),
                      [&](std::uint32_t x, std::uint32_t y) { return area(x) > area(y); });
    std::size_t answers = 0;
    bool outside = true;
    for (std::size_t k = 0; k < probes && outside; ++k) {
      const auto& t = mesh.triangles[largest[k]];
      const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
      const dvec3 normal = glm::cross(b - a, c - a);
      if (normal == dvec3(0.0)) continue;
      // Into the shell's material, which lies behind its faces.
      const dvec3 inward = -glm::normalize(normal);
      const dvec3 centre = (a + b + c) / 3.0;
      // The nearest face of any shell: another may lie within this one.
      const double through = firstCrossing(mesh, allFaces, largest[k], centre, inward);
      if (through == kInfinity) continue;
      ++answers;
      outside = !solid.contains(centre + 0.5 * through * inward);
    }
    if (!outside || answers < kAnswers) continue;
    ++removed;
    for (std::uint32_t f : faces) stray[f] = true;
  }
  if (removed == 0) return 0;

  // The part without them, its points renumbered.
  PartMesh kept;
  kept.materials = part.materials;
  std::vector<std::uint32_t> index(mesh.points.size(), UINT32_MAX);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    if (stray[f]) continue;
    TriangleMesh::Triangle t = mesh.triangles[f];
    for (auto& v : t) {
      if (index[v] == UINT32_MAX) {
        index[v] = std::uint32_t(kept.mesh.points.size());
        kept.mesh.points.push_back(mesh.points[v]);
      }
      v = index[v];
    }
    kept.mesh.triangles.push_back(t);
    kept.material.push_back(part.material[f]);
  }
  part = std::move(kept);
  return removed;
}

}  // namespace csgray::detail
