#include "export/aligned_walls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace csgray::detail {

namespace {

// A line along the axis, by its two other coordinates, and the mesh whose
// edge lies on it.
struct Line {
  double u, v;
  std::uint32_t mesh;
  bool at(const Line& other) const { return u == other.u && v == other.v; }
};

using Spot = std::pair<double, double>;

// The lines along `axis` (0, 1, 2) that the meshes' edges lie on, sorted
// by where they are, each once per mesh.
std::vector<Line> linesAlong(std::span<TriangleMesh* const> meshes, int axis) {
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  std::vector<Line> lines;
  for (std::uint32_t i = 0; i < meshes.size(); ++i) {
    const TriangleMesh& mesh = *meshes[i];
    for (const TriangleMesh::Triangle& t : mesh.triangles)
      for (int c = 0; c < 3; ++c) {
        const dvec3& p = mesh.points[t[c]];
        const dvec3& q = mesh.points[t[(c + 1) % 3]];
        if (p[a] == q[a] && p[b] == q[b] && p[axis] != q[axis]) lines.push_back({p[a], p[b], i});
      }
  }
  auto key = [](const Line& l) { return std::tuple(l.u, l.v, l.mesh); };
  std::sort(lines.begin(), lines.end(),
            [&](const Line& l, const Line& r) { return key(l) < key(r); });
  lines.erase(std::unique(lines.begin(), lines.end(),
                          [](const Line& l, const Line& r) { return l.at(r) && l.mesh == r.mesh; }),
              lines.end());
  return lines;
}

}  // namespace

std::vector<bool> alignAxisLines(std::span<TriangleMesh* const> meshes, double reach) {
  std::vector<bool> moved(meshes.size(), false);
  if (meshes.size() < 2 || !(reach > 0.0)) return moved;
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<Line> lines = linesAlong(meshes, axis);
    // Each line's target: the spot of the earlier mesh's line it comes
    // within reach of. A line that already lies at another mesh's line,
    // or that comes near two spots, stays.
    enum class State { Free, Target, Stays };
    std::vector<State> state(lines.size(), State::Free);
    std::vector<Spot> target(lines.size());
    auto offer = [&](std::size_t later, const Line& earlier) {
      const Spot spot(earlier.u, earlier.v);
      if (lines[later].at(earlier)) {
        state[later] = State::Stays;
      } else if (state[later] == State::Free) {
        state[later] = State::Target;
        target[later] = spot;
      } else if (state[later] == State::Target && target[later] != spot) {
        state[later] = State::Stays;
      }
    };
    for (std::size_t i = 0; i < lines.size(); ++i)
      for (std::size_t j = i + 1; j < lines.size() && lines[j].u - lines[i].u <= reach; ++j) {
        if (lines[i].mesh == lines[j].mesh || std::abs(lines[j].v - lines[i].v) > reach) continue;
        if (lines[i].mesh < lines[j].mesh)
          offer(j, lines[i]);
        else
          offer(i, lines[j]);
      }
    // A line stays where the spot it would move to moves itself, or where
    // its mesh has another line at that spot or moving to it (the faces
    // between the two would fold).
    std::map<Spot, bool> spotMoves;
    std::map<std::pair<std::uint32_t, Spot>, int> arrivals;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const Spot here(lines[i].u, lines[i].v);
      bool& moves = spotMoves[here];
      moves = moves || state[i] == State::Target;
      ++arrivals[{lines[i].mesh, state[i] == State::Target ? target[i] : here}];
    }
    std::vector<std::map<Spot, Spot>> moves(meshes.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (state[i] != State::Target) continue;
      if (spotMoves[target[i]] || arrivals[{lines[i].mesh, target[i]}] > 1) continue;
      moves[lines[i].mesh][Spot(lines[i].u, lines[i].v)] = target[i];
    }
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      if (moves[m].empty()) continue;
      for (dvec3& p : meshes[m]->points) {
        const auto found = moves[m].find(Spot(p[a], p[b]));
        if (found == moves[m].end()) continue;
        p[a] = found->second.first;
        p[b] = found->second.second;
        moved[m] = true;
      }
    }
  }
  return moved;
}

}  // namespace csgray::detail
