#include "export/collinear_points.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <span>
#include <unordered_map>

namespace csgray::detail {

namespace {
using Triangle = TriangleMesh::Triangle;

// The faces around each point, in one array (compressed rows): the faces
// of point v are faces[first[v]] to faces[first[v + 1]].
struct FacesAround {
  std::vector<std::uint32_t> first, faces;

  FacesAround(const std::vector<Triangle>& triangles, std::size_t points) : first(points + 1, 0) {
    for (const Triangle& t : triangles)
      for (std::uint32_t v : t) ++first[v + 1];
    for (std::size_t v = 0; v < points; ++v) first[v + 1] += first[v];
    faces.resize(first[points]);
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (std::uint32_t v : triangles[f]) faces[next[v]++] = std::uint32_t(f);
  }
  std::span<const std::uint32_t> of(std::uint32_t v) const {
    return {faces.data() + first[v], faces.data() + first[v + 1]};
  }
};

// The most faces around a point that is looked at: a point of a crease
// has a few.
constexpr std::size_t kMostFaces = 64;

// The fan of faces around a point v, in order: face i is (v, ring[i],
// ring[i + 1]), the ring closing on itself.
struct Fan {
  std::size_t size = 0;
  std::array<std::uint32_t, kMostFaces> face, ring;
};

// False when the faces around v do not make one closed fan.
bool fanAround(std::uint32_t v, std::span<const std::uint32_t> around,
               const std::vector<Triangle>& triangles, Fan& fan) {
  const std::size_t k = around.size();
  fan.size = k;
  if (k < 3 || k > kMostFaces) return false;
  // Each face's corners after v.
  std::array<std::array<std::uint32_t, 2>, kMostFaces> after;
  for (std::size_t i = 0; i < k; ++i) {
    const Triangle& t = triangles[around[i]];
    const int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    after[i] = {t[(at + 1) % 3], t[(at + 2) % 3]};
  }
  std::size_t i = 0;
  for (std::size_t step = 0; step < k; ++step) {
    fan.face[step] = around[i];
    fan.ring[step] = after[i][0];
    // The next face starts where this one ends.
    const std::uint32_t y = after[i][1];
    i = 0;
    while (i < k && after[i][0] != y) ++i;
    // No next face, or back at the first too soon (two fans meet at v).
    if (i == k || (i == 0 && step + 1 < k)) return false;
  }
  return i == 0;
}

class Collapser {
 public:
  Collapser(TriangleMesh& mesh, std::vector<std::uint32_t>& tags, double reach)
      : mesh_(mesh),
        tags_(tags),
        reach_(reach),
        alive_(mesh.triangles.size(), true),
        around_(mesh.triangles, mesh.points.size()) {}

  // Which points lie on a crease is asked of each on its own, on all
  // threads; the collapses are then made in the points' order, on one
  // thread, each asked again of the mesh as the ones before it left it.
  std::size_t run() {
    const std::size_t points = mesh_.points.size();
    std::vector<char> onCrease(points, 0);
    auto ask = [&](std::size_t from, std::size_t to) {
      Fan fan;
      Crease crease;
      for (std::size_t v = from; v < to; ++v)
        onCrease[v] =
            fanAround(std::uint32_t(v), around_.of(std::uint32_t(v)), mesh_.triangles, fan) &&
            creaseThrough(std::uint32_t(v), fan, crease);
    };
    // Small meshes stay on this thread (TBB's start costs about half a
    // millisecond).
    if (points >= 10000)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points, 4096),
                        [&](const auto& range) { ask(range.begin(), range.end()); });
    else
      ask(0, points);

    std::size_t dropped = 0;
    Fan fan;
    Crease crease;
    std::vector<std::uint32_t> faces, intoFaces;
    for (std::uint32_t v = 0; v < points; ++v) {
      if (!onCrease[v]) continue;
      facesOf(v, faces);
      if (!fanAround(v, faces, mesh_.triangles, fan) || !creaseThrough(v, fan, crease)) continue;
      for (const std::size_t end : {crease.a, crease.b}) {
        const std::uint32_t into = fan.ring[end];
        facesOf(into, intoFaces);
        if (!canCollapse(v, fan, crease, end, intoFaces)) continue;
        collapse(v, fan, into);
        ++dropped;
        break;
      }
    }
    return dropped;
  }

  // The mesh without the dead faces and the points no face uses.
  void compact() {
    std::vector<std::uint32_t> index(mesh_.points.size(), UINT32_MAX);
    std::size_t kept = 0;
    for (std::size_t f = 0; f < mesh_.triangles.size(); ++f) {
      if (!alive_[f]) continue;
      mesh_.triangles[kept] = mesh_.triangles[f];
      tags_[kept] = tags_[f];
      ++kept;
    }
    mesh_.triangles.resize(kept), tags_.resize(kept);
    for (const Triangle& t : mesh_.triangles)
      for (std::uint32_t v : t) index[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < mesh_.points.size(); ++v)
      if (index[v] == 0) {
        index[v] = next;
        mesh_.points[next++] = mesh_.points[v];
      }
    mesh_.points.resize(next);
    for (Triangle& t : mesh_.triangles)
      for (std::uint32_t& v : t) v = index[v];
  }

 private:
  // The two flat sides of a crease through a point: the fan's faces from
  // ring[a] to ring[b] lie in one plane, those from ring[b] back to ring[a]
  // in the other.
  struct Crease {
    std::size_t a = 0, b = 0;
    dvec3 normal[2];  // of the side after a, of the side after b
  };

  bool creaseThrough(std::uint32_t v, const Fan& fan, Crease& crease) const {
    const std::size_t k = fan.size;
    const dvec3& at = mesh_.points[v];
    auto corner = [&](std::size_t i) { return mesh_.points[fan.ring[i % k]] - at; };
    // Face i's normal, its length twice its area.
    std::array<dvec3, kMostFaces> normal;
    std::array<double, kMostFaces> area;
    auto measure = [&](std::size_t i) {
      normal[i] = glm::cross(corner(i), corner(i + 1));
      area[i] = glm::length(normal[i]);
    };
    // Are face j's corners in face i's plane (through v)?
    auto inPlaneOf = [&](std::size_t j, std::size_t i) {
      const double reach = reach_ * area[i];
      return std::abs(glm::dot(corner(j), normal[i])) <= reach &&
             std::abs(glm::dot(corner(j + 1), normal[i])) <= reach;
    };
    // Of two faces, one in the plane of the larger.
    auto coplanar = [&](std::size_t i, std::size_t j) {
      return area[i] >= area[j] ? inPlaneOf(j, i) : inPlaneOf(i, j);
    };
    // Around a crease the plane changes twice from face to face; around a
    // point of a curved face (most points) more often, which is seen
    // before all its faces are measured.
    std::size_t turns = 0;
    measure(0);
    for (std::size_t i = 0; i < k; ++i) {
      if (i + 1 < k) measure(i + 1);
      turns += !coplanar(i, (i + 1) % k);
      if (turns > 2) return false;
    }
    if (turns != 2) return false;
    // The plane of the largest face of the fan, then that of the largest
    // face off it: the faces must all lie in one of the two.
    const std::size_t first = std::max_element(area.begin(), area.begin() + k) - area.begin();
    if (!(area[first] > 0.0)) return false;
    std::array<bool, kMostFaces> side;
    std::size_t second = k;
    for (std::size_t i = 0; i < k; ++i) {
      side[i] = !inPlaneOf(i, first);
      if (side[i] && (second == k || area[i] > area[second])) second = i;
    }
    if (second == k || !(area[second] > 0.0)) return false;  // a flat point, not on a crease
    for (std::size_t i = 0; i < k; ++i)
      if (side[i] && !inPlaneOf(i, second)) return false;
    // Each side one run of faces: two changes of side around the fan.
    std::size_t changes = 0;
    for (std::size_t i = 0; i < k; ++i) {
      if (side[i] == side[(i + k - 1) % k]) continue;
      ++changes;
      (side[i] ? crease.b : crease.a) = i;
    }
    if (changes != 2) return false;
    // The run on the first side goes from ring[a] to ring[b].
    crease.normal[0] = normal[first] / area[first];
    crease.normal[1] = normal[second] / area[second];
    // v on the straight line between the crease's ends, and between them.
    const dvec3 &pa = mesh_.points[fan.ring[crease.a]], &pb = mesh_.points[fan.ring[crease.b]];
    const dvec3 ab = pb - pa;
    const double length2 = glm::dot(ab, ab);
    if (!(length2 > 0.0)) return false;
    const double along = glm::dot(at - pa, ab);
    if (!(along > 0.0 && along < length2)) return false;
    return glm::length(glm::cross(at - pa, ab)) <= reach_ * std::sqrt(length2);
  }

  // Can v go to ring[end], one end of its crease? The faces left must face
  // the way their side does, with area, and hold one material per side;
  // v and its end may share no neighbour but the two faces' third corners
  // (else the mesh would pinch).
  bool canCollapse(std::uint32_t v, const Fan& fan, const Crease& crease, std::size_t end,
                   std::span<const std::uint32_t> intoFaces) const {
    const std::size_t k = fan.size;
    const std::uint32_t into = fan.ring[end];
    const dvec3& p = mesh_.points[into];
    // Side 0 runs ring[a] → ring[b], side 1 ring[b] → ring[a].
    for (std::size_t i = 0; i < k; ++i) {
      const std::uint32_t x = fan.ring[i], y = fan.ring[(i + 1) % k];
      const bool onFirst =
          crease.a <= crease.b ? (i >= crease.a && i < crease.b) : (i >= crease.a || i < crease.b);
      if (tags_[fan.face[i]] != tags_[fan.face[onFirst ? crease.a : crease.b]]) return false;
      if (x == into || y == into) continue;  // the face goes
      const dvec3 n = glm::cross(mesh_.points[x] - p, mesh_.points[y] - p);
      const double scale = glm::length(mesh_.points[x] - p) * glm::length(mesh_.points[y] - p);
      if (!(glm::dot(n, crease.normal[onFirst ? 0 : 1]) > 1e-9 * scale)) return false;
    }
    // The link: ring points other than the two beside `into` must not
    // already be joined to it.
    const std::uint32_t before = fan.ring[(end + k - 1) % k], after = fan.ring[(end + 1) % k];
    for (std::uint32_t f : intoFaces)
      for (std::uint32_t w : mesh_.triangles[f]) {
        if (w == into || w == v || w == before || w == after) continue;
        if (std::find(fan.ring.begin(), fan.ring.begin() + k, w) != fan.ring.begin() + k)
          return false;
      }
    return true;
  }

  // The faces around v now: those it had at the start that are still
  // there, and those a point collapsed into it brought.
  void facesOf(std::uint32_t v, std::vector<std::uint32_t>& faces) const {
    faces.clear();
    auto holds = [&](std::uint32_t f) {
      const Triangle& t = mesh_.triangles[f];
      return alive_[f] && (t[0] == v || t[1] == v || t[2] == v);
    };
    for (std::uint32_t f : around_.of(v))
      if (holds(f)) faces.push_back(f);
    if (auto brought = brought_.find(v); brought != brought_.end())
      for (std::uint32_t f : brought->second)
        if (holds(f)) faces.push_back(f);
  }

  void collapse(std::uint32_t v, const Fan& fan, std::uint32_t into) {
    auto& brought = brought_[into];
    for (std::size_t i = 0; i < fan.size; ++i) {
      const std::uint32_t f = fan.face[i];
      Triangle& t = mesh_.triangles[f];
      if (t[0] == into || t[1] == into || t[2] == into) {
        alive_[f] = false;
        continue;
      }
      for (std::uint32_t& w : t)
        if (w == v) w = into;
      brought.push_back(f);
    }
  }

  TriangleMesh& mesh_;
  std::vector<std::uint32_t>& tags_;
  const double reach_;
  std::vector<bool> alive_;
  const FacesAround around_;  // as at the start
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> brought_;
};

}  // namespace

std::size_t dropCollinearPoints(TriangleMesh& mesh, std::vector<std::uint32_t>& tags,
                                double reach) {
  Collapser collapser(mesh, tags, reach);
  const std::size_t dropped = collapser.run();
  if (dropped > 0) collapser.compact();
  return dropped;
}

}  // namespace csgray::detail
