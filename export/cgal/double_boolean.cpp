#include "export/cgal/double_boolean.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "engine/cancellation.h"
#include "export/cgal/box_pairs.h"

namespace csgray::detail {

namespace {

using K = CGAL::Epick;
using Point = K::Point_3;
using Id = std::uint32_t;  // a vertex: the operands' points, then the crossings
using Triangle = std::array<Id, 3>;

// Thrown where the operands are not in general position or a step finds
// something inconsistent (or, with NotInDoubles, where an operand is not
// one it can take); doubleBoolean then declines.
struct Declined {
  DoubleDecline why = DoubleDecline::NotInGeneralPosition;
};

// An edge: its ends' ids, the lower first. (The two operands' ids differ,
// so it also says whose edge it is.)
using EdgeKey = std::uint64_t;
EdgeKey pairKey(Id a, Id b) { return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// A crossing: the edge and the other operand's face it passes through,
// or the two edges (the first operand's first) where it is on an edge of
// that face. (An edge's key is at least 2³² since the second operand's
// ids start after the first's, so the two kinds never meet.)
using CrossingKey = std::pair<std::uint64_t, std::uint64_t>;

// One operand: its faces, their corners as global ids.
struct Operand {
  Id base = 0;  // the global id of its vertex 0
  Id size = 0;  // its number of points
  std::vector<Triangle> corners;
  std::vector<std::uint32_t> tags;
  std::vector<std::uint32_t> faces;  // 0, 1, ...: each face's index

  EdgeKey edge(std::uint32_t f, int k) const {
    return pairKey(corners[f][k], corners[f][(k + 1) % 3]);
  }
};

// A piece of a face after the cut: a triangle of global ids.
struct Piece {
  Triangle corners;
  std::uint32_t face;
};

// Where an edge of one operand crosses a face of the other: the part of
// the edge from the crossing towards `from` lies inside the other operand
// when fromInside.
struct Crossing {
  Id point;
  Id from;
  EdgeKey edge;
  bool fromInside;
};

// An edge k of a face of operand `side` that passes through the face of
// the other operand it is paired with (pairs[pair] of findCrossings): its
// start on side fromSide of that face's plane, the crossing at `ratio` of
// the way along it, through edge onEdge of the other face (unperturbed)
// or, at -1, through its inside.
struct EdgeThrough {
  std::uint32_t pair;
  std::uint8_t side, k;
  std::int8_t onEdge;
  CGAL::Orientation fromSide;
  double ratio;
  CrossingKey key;  // the crossing's, which the other pairs that find it share
};

// The boolean's working state: the points, the crossings found, and what
// each face of each operand is to be cut along.
class DoubleBoolean {
 public:
  DoubleBoolean(const DoubleMesh& a, const DoubleMesh& b) : meshes_{&a, &b} {
    // Each operand's points have a range of ids of their own (the first
    // operand's, then the second's), so the two load at once.
    ops_[0].size = Id(a.mesh.points.size());
    ops_[1].size = Id(b.mesh.points.size());
    ops_[1].base = ops_[0].size;
    points_.resize(a.mesh.points.size() + b.mesh.points.size());
    tbb::parallel_invoke([&] { load(0); }, [&] { load(1); });
  }

  std::optional<DoubleMesh> run(Boolean::Op op) {
    findCrossings();
    stopIfCancelled(cancel_);
    // Once the crossings are found, each operand is cut and classified
    // from its own state (its edges' points, faces, pieces; the other's
    // point test, built by this operand only) and the shared points and
    // segments are only read: the two run at once, and what each makes
    // does not depend on the other's progress.
    auto cutAndClassify = [this](int s) {
      sortEdgePoints(s);
      cutFaces(s);
      stopIfCancelled(cancel_);
      classify(s);
    };
    tbb::parallel_invoke([&] { cutAndClassify(0); }, [&] { cutAndClassify(1); });
    stopIfCancelled(cancel_);
    return assemble(op);
  }

 private:
  // The operand's points and faces. Each face (a, b, c) is read from c
  // on, as (c, a, b): where CGAL's mesh was made from it (add_face(a, b,
  // c)), that is where the face's halfedge starts, which is how these
  // booleans read CGAL's meshes before they took doubles; the points it
  // makes are numbered in that order, and so stay as they were.
  void load(int s) {
    const TriangleMesh& mesh = meshes_[s]->mesh;
    Operand& op = ops_[s];
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
      const dvec3& p = mesh.points[v];
      points_[op.base + v] = Point(p.x, p.y, p.z);
    }
    const std::size_t count = mesh.triangles.size();
    op.corners.resize(count);
    op.faces.resize(count);
    for (std::size_t f = 0; f < count; ++f) {
      const auto& t = mesh.triangles[f];
      op.corners[f] = {op.base + t[2], op.base + t[0], op.base + t[1]};
      op.faces[f] = std::uint32_t(f);
    }
    op.tags = meshes_[s]->tags;
    faceSegments_[s].resize(count);
    facePoints_[s].resize(count);
  }

  const Point& at(Id id) const { return points_[id]; }

  // The pairs of faces whose boxes meet, each tested. The tests (exact
  // predicates that only read the operands) run on all threads, in blocks
  // of pairs; the crossings they find are then numbered in the pairs'
  // order, which depends only on the operands (numberCrossings): so the
  // new points' ids do not depend on the threads.
  void findCrossings() {
    std::vector<FaceBox> boxes[2];
    for (int s = 0; s < 2; ++s) {
      boxes[s].reserve(ops_[s].faces.size());
      for (std::uint32_t f : ops_[s].faces) {
        const Triangle& t = ops_[s].corners[f];
        boxes[s].push_back(faceBox(at(t[0]), at(t[1]), at(t[2]), f, std::uint32_t(s)));
      }
    }
    const std::vector<FacePair> pairs = meetingPairs(boxes[0], boxes[1]);
    // Blocks of a fixed size, so that the blocks do not depend on the threads either.
    constexpr std::size_t kBlock = 4096;
    std::vector<std::vector<EdgeThrough>> found((pairs.size() + kBlock - 1) / kBlock);
    tbb::parallel_for(std::size_t(0), found.size(), [&](std::size_t block) {
      stopIfCancelled(cancel_);
      const std::size_t end = std::min(pairs.size(), (block + 1) * kBlock);
      for (std::size_t i = block * kBlock; i < end; ++i) edgesThrough(pairs[i], i, found[block]);
    });
    std::vector<std::size_t> offset(found.size() + 1, 0);
    for (std::size_t block = 0; block < found.size(); ++block)
      offset[block + 1] = offset[block] + found[block].size();
    std::vector<EdgeThrough> all(offset.back());
    tbb::parallel_for(std::size_t(0), found.size(), [&](std::size_t block) {
      std::copy(found[block].begin(), found[block].end(), all.begin() + offset[block]);
    });
    found = {};
    numberCrossings(pairs, all);
  }

  // Each crossing found (by two pairs of faces or more) made one point,
  // numbered in the order the pairs first find them, which depends on the
  // operands only; then the points each face and edge holds, and each
  // pair's segment. The crossings that one crossing's finds share are
  // told by sorting their keys; the points are made, and each operand's
  // lists filled, on all threads, each list in that order.
  void numberCrossings(const std::vector<FacePair>& pairs, const std::vector<EdgeThrough>& all) {
    const std::size_t total = all.size();
    struct Keyed {
      CrossingKey key;
      std::uint32_t at;
      bool operator<(const Keyed& other) const {
        return key != other.key ? key < other.key : at < other.at;
      }
    };
    std::vector<Keyed> keyed(total);
    tbb::parallel_for(std::size_t(0), total, [&](std::size_t i) {
      keyed[i] = {all[i].key, std::uint32_t(i)};
    });
    tbb::parallel_sort(keyed.begin(), keyed.end());
    // first[i]: the first find of the crossing that find i finds.
    std::vector<std::uint32_t> first(total);
    tbb::parallel_for(std::size_t(0), total, [&](std::size_t j) {
      if (j > 0 && keyed[j - 1].key == keyed[j].key) return;
      for (std::size_t k = j; k < total && keyed[k].key == keyed[j].key; ++k)
        first[keyed[k].at] = keyed[j].at;
    });
    keyed = {};
    std::vector<Id> ids(total);
    Id next = Id(points_.size());
    for (std::size_t i = 0; i < total; ++i) ids[i] = first[i] == i ? next++ : ids[first[i]];
    points_.resize(next);
    std::atomic<bool> outside = false;
    tbb::parallel_for(std::size_t(0), total, [&](std::size_t i) {
      if (first[i] != i) return;
      const EdgeThrough& e = all[i];
      const double u = e.ratio;
      if (!(u >= 0.0 && u <= 1.0)) {
        outside = true;
        return;
      }
      const auto [p, q] = edgeEnds(e, pairs[e.pair]);
      points_[ids[i]] = at(p) + u * (at(q) - at(p));
    });
    if (outside) throw Declined{};
    segments_.reserve(total / 2);
    tbb::parallel_invoke([&] { recordCrossings(0, pairs, all, first, ids); },
                         [&] { recordCrossings(1, pairs, all, first, ids); });
  }

  // The ends of the edge that passes through the other face.
  std::pair<Id, Id> edgeEnds(const EdgeThrough& e, const FacePair& pair) const {
    const Triangle& t = ops_[e.side].corners[e.side == 0 ? pair.first : pair.second];
    return {t[e.k], t[(e.k + 1) % 3]};
  }

  // What operand s holds of the crossings numbered: the points on its
  // edges and inside its faces, the crossings of its edges, its faces'
  // segments; in the order of the finds, as they would be numbered one by
  // one. (Each operand's lists are its own: the two are filled at once.)
  void recordCrossings(int s, const std::vector<FacePair>& pairs,
                       const std::vector<EdgeThrough>& all, const std::vector<std::uint32_t>& first,
                       const std::vector<Id>& ids) {
    for (std::size_t i = 0; i < all.size();) {
      std::size_t end = i + 1;
      while (end < all.size() && all[end].pair == all[i].pair) ++end;
      const FacePair& pair = pairs[all[i].pair];
      for (std::size_t j = i; j < end; ++j) {
        if (first[j] != j) continue;
        const EdgeThrough& e = all[j];
        const Id id = ids[j];
        const auto [p, q] = edgeEnds(e, pair);
        if (e.side == s) {
          // Along the edge from its lower id to its higher one.
          const EdgeKey edge = pairKey(p, q);
          edgePoints_[s][edge].push_back({p < q ? e.ratio : 1.0 - e.ratio, id});
          crossings_[s].push_back({id, p, edge, e.fromSide == CGAL::NEGATIVE});
          continue;
        }
        const std::uint32_t g = s == 0 ? pair.first : pair.second;
        if (e.onEdge == -1) {
          facePoints_[s][g].push_back(id);
          continue;
        }
        const Triangle& t = ops_[s].corners[g];
        const Id a = std::min(t[e.onEdge], t[(e.onEdge + 1) % 3]),
                 b = std::max(t[e.onEdge], t[(e.onEdge + 1) % 3]);
        const auto along = at(b) - at(a);
        const double w =
            std::clamp(((points_[id] - at(a)) * along) / along.squared_length(), 0.0, 1.0);
        edgePoints_[s][pairKey(a, b)].push_back({w, id});
      }
      // The pair's segment, between the points where its edges cross the
      // other face. Where an edge of each crosses the other's (in the
      // input, before the perturbation) the segment is infinitesimal:
      // both are one point, and the segment is left out.
      const std::size_t n = end - i;
      const Id from = ids[i], to = ids[i + 1 < end ? i + 1 : i];
      i = end;
      if (n == 2 && from == to) continue;
      if (n != 2) throw Declined{};
      faceSegments_[s][s == 0 ? pair.first : pair.second].push_back({from, to});
      if (s == 0) segments_.insert(pairKey(from, to));
    }
  }

  // The predicates below are exact, and where one is zero the operands
  // are taken as they would be with the second moved by an infinitesimal
  // δ = (ε, ε², ε³): a simulation of simplicity (Edelsbrunner and Mücke,
  // "Simulation of Simplicity", ACM Trans. Graphics 9(1), 1990). Each is
  // linear in δ, so its sign is that of the first nonzero coordinate of
  // its gradient, x before y before z; every decision is made for one
  // and the same perturbed input, so they agree with each other.

  // The sign of the x, y or z coordinate of (b − a) × (d − c), exactly.
  static CGAL::Sign crossSign(const Point& a, const Point& b, const Point& c, const Point& d,
                              int axis) {
    using FT = CGAL::Epeck::FT;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return CGAL::sign((FT(b[i]) - FT(a[i])) * (FT(d[j]) - FT(c[j])) -
                      (FT(b[j]) - FT(a[j])) * (FT(d[i]) - FT(c[i])));
  }

  // The side of point p (of operand 1 − s) against the plane of triangle
  // t (of operand s). orient3d(t, p) = n·(p − t₀) with n = (t₁ − t₀) ×
  // (t₂ − t₀); with the second operand moved by δ it gains ±n·δ.
  CGAL::Orientation sideOf(int s, const Triangle& t, Id p) const {
    const CGAL::Orientation o = CGAL::orientation(at(t[0]), at(t[1]), at(t[2]), at(p));
    if (o != CGAL::ZERO) return o;
    for (int axis = 0; axis < 3; ++axis) {
      // The normal's coordinate: an orient2d of the triangle.
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      const auto flat = [&](Id v) { return K::Point_2(at(v)[i], at(v)[j]); };
      const CGAL::Orientation n = CGAL::orientation(flat(t[0]), flat(t[1]), flat(t[2]));
      if (n == CGAL::ZERO) continue;
      // A corner on the other's face, not beside it in its plane: the
      // solids would touch there (or the perturbation would part them
      // by a point contact, which the export's check refuses).
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside = inside && CGAL::orientation(flat(t[k]), flat(t[(k + 1) % 3]), flat(p)) != -n;
      if (inside) throw Declined{};
      return s == 0 ? n : -n;
    }
    throw Declined{};  // a triangle without area
  }

  // orient3d(p, q, a, b) for an edge pq of operand s and an edge ab of the
  // other: it gains δ·((b − a) × (q − p)) when ab is moved by δ.
  CGAL::Orientation turnOf(int s, Id p, Id q, Id a, Id b) const {
    const CGAL::Orientation o = CGAL::orientation(at(p), at(q), at(a), at(b));
    if (o != CGAL::ZERO) return o;
    for (int axis = 0; axis < 3; ++axis) {
      const CGAL::Sign c = crossSign(at(a), at(b), at(p), at(q), axis);
      if (c != CGAL::ZERO) return s == 0 ? c : -c;
    }
    throw Declined{};  // parallel edges in one plane
  }

  // The sides of a triangle's corners against the plane of another, of
  // the other operand s.
  std::array<CGAL::Orientation, 3> sides(const Triangle& t, int s, const Triangle& plane) const {
    std::array<CGAL::Orientation, 3> o;
    for (int k = 0; k < 3; ++k) o[k] = sideOf(s, plane, t[k]);
    return o;
  }

  static bool across(const std::array<CGAL::Orientation, 3>& o) {
    return !(o[0] == o[1] && o[1] == o[2]);
  }

  // Faces fa of the first operand and fb of the second: in general
  // position they meet along one segment, between two points where an
  // edge of one crosses the other. The edges of either face that pass
  // through the other are appended to `out`, in the order cutAlong
  // numbers them, with the pair's index.
  void edgesThrough(const FacePair& pair, std::size_t index, std::vector<EdgeThrough>& out) const {
    const auto [fa, fb] = pair;
    const Triangle& ta = ops_[0].corners[fa];
    const Triangle& tb = ops_[1].corners[fb];
    const auto oa = sides(ta, 1, tb);
    if (!across(oa)) return;
    const auto ob = sides(tb, 0, ta);
    if (!across(ob)) return;
    for (int s = 0; s < 2; ++s) {
      const auto& o = s == 0 ? oa : ob;
      for (int k = 0; k < 3; ++k)
        if (o[k] != o[(k + 1) % 3])
          if (auto through = edgeThrough(s, s == 0 ? fa : fb, k, s == 0 ? fb : fa)) {
            through->pair = std::uint32_t(index);
            through->fromSide = o[k];
            through->key = crossingKey(*through, pair);
            out.push_back(*through);
          }
    }
  }

  // The key of the crossing an edge makes (EdgeThrough::key).
  CrossingKey crossingKey(const EdgeThrough& e, const FacePair& pair) const {
    const auto [p, q] = edgeEnds(e, pair);
    const std::uint32_t g = e.side == 0 ? pair.second : pair.first;
    if (e.onEdge == -1) return {pairKey(p, q), g};
    const EdgeKey otherEdge = ops_[1 - e.side].edge(g, e.onEdge);
    return e.side == 0 ? CrossingKey{pairKey(p, q), otherEdge}
                       : CrossingKey{otherEdge, pairKey(p, q)};
  }

  // Whether edge k of face f of operand s passes through face g of the
  // other, and where: the fraction of the way along it.
  std::optional<EdgeThrough> edgeThrough(int s, std::uint32_t f, int k, std::uint32_t g) const {
    const Triangle& t = ops_[s].corners[f];
    const Triangle& other = ops_[1 - s].corners[g];
    const Id p = t[k], q = t[(k + 1) % 3];
    // The line pq passes inside the triangle where it turns the same way
    // about all three of its edges (orient3d; Shewchuk, "Adaptive
    // Precision Floating-Point Arithmetic and Fast Robust Geometric
    // Predicates", 1997, for the predicate).
    CGAL::Orientation turn[3];
    int onEdge = -1;  // the edge of g that pq meets, unperturbed
    for (int i = 0; i < 3; ++i) {
      const Id a = other[i], b = other[(i + 1) % 3];
      turn[i] = turnOf(s, p, q, a, b);
      if (CGAL::orientation(at(p), at(q), at(a), at(b)) == CGAL::ZERO) {
        if (onEdge != -1) throw Declined{};  // through a corner of g
        onEdge = i;
      }
    }
    if (turn[0] != turn[1] || turn[1] != turn[2]) return std::nullopt;  // passes outside
    // The point on pq at the plane: signed distances dp, dq of its ends
    // (up to the normal's length), pq cut at dp / (dp − dq).
    const Point &a = at(other[0]), &b = at(other[1]), &c = at(other[2]);
    const auto normal = CGAL::cross_product(b - a, c - a);
    const double dp = normal * (at(p) - a), dq = normal * (at(q) - a);
    // (dp = dq = 0: pq in g's plane, which only the perturbation parts.)
    EdgeThrough through;
    through.side = std::uint8_t(s);
    through.k = std::uint8_t(k);
    through.onEdge = std::int8_t(onEdge);
    through.ratio = dp / (dp - dq);
    return through;
  }

  // Each cut edge's points in order from its lower id; two at one place:
  // Declined.
  void sortEdgePoints(int s) {
    for (auto& [edge, list] : edgePoints_[s]) {
      std::sort(list.begin(), list.end());
      for (std::size_t i = 1; i < list.size(); ++i)
        if (!(list[i - 1].first < list[i].first)) throw Declined{};
    }
  }

  // The points of face f's boundary in order, its corners and the points
  // on its edges.
  std::vector<Id> boundaryOf(int s, std::uint32_t f) const {
    const Operand& op = ops_[s];
    std::vector<Id> ring;
    for (int k = 0; k < 3; ++k) {
      const Id p = op.corners[f][k], q = op.corners[f][(k + 1) % 3];
      ring.push_back(p);
      auto it = edgePoints_[s].find(op.edge(f, k));
      if (it == edgePoints_[s].end()) continue;
      if (p < q)
        for (const auto& [u, id] : it->second) ring.push_back(id);
      else
        for (auto e = it->second.rbegin(); e != it->second.rend(); ++e) ring.push_back(e->second);
    }
    return ring;
  }

  // Every face of operand s, cut along its segments into pieces.
  void cutFaces(int s) {
    const Operand& op = ops_[s];
    pieces_[s].reserve(op.faces.size());
    for (std::uint32_t f : op.faces) {
      if (faceSegments_[s][f].empty()) {
        pieces_[s].push_back({op.corners[f], f});
        continue;
      }
      stopIfCancelled(cancel_);
      if (!cutOnce(s, f)) cutFace(s, f);
    }
  }

  // A face crossed by one segment from edge to edge (most cut faces), in
  // two convex pieces, a triangle and a quadrilateral (the triangle cut by
  // a line), without a triangulation: the quadrilateral along its shorter
  // diagonal. False for any other face.
  bool cutOnce(int s, std::uint32_t f) {
    if (faceSegments_[s][f].size() != 1 || !facePoints_[s][f].empty()) return false;
    const std::vector<Id> ring = boundaryOf(s, f);
    if (ring.size() != 5) return false;
    const auto [x, y] = faceSegments_[s][f][0];
    const int i = int(std::find(ring.begin(), ring.end(), x) - ring.begin());
    const int j = int(std::find(ring.begin(), ring.end(), y) - ring.begin());
    if (i == 5 || j == 5) throw Declined{};
    // The piece from one end to the other along the ring, and the rest.
    const int from = std::min(i, j), to = std::max(i, j);
    std::vector<Id> one(ring.begin() + from, ring.begin() + to + 1), other;
    for (int k = to; k != from + 5; ++k) other.push_back(ring[k % 5]);
    other.push_back(ring[from]);
    if (one.size() < 3 || other.size() < 3) throw Declined{};  // along an edge
    for (const std::vector<Id>* polygon : {&one, &other}) {
      const std::vector<Id>& p = *polygon;
      if (p.size() == 3) {
        pieces_[s].push_back({{p[0], p[1], p[2]}, f});
        continue;
      }
      const bool first =
          CGAL::squared_distance(at(p[0]), at(p[2])) <= CGAL::squared_distance(at(p[1]), at(p[3]));
      const int d = first ? 0 : 1;
      pieces_[s].push_back({{p[d], p[d + 1], p[d + 2]}, f});
      pieces_[s].push_back({{p[d], p[d + 2], p[(d + 3) % 4]}, f});
    }
    return true;
  }

  // A cut face: the constrained Delaunay triangulation of its boundary
  // (corners and the points on its edges), the crossings inside it and its
  // segments, in the plane of the normal's largest coordinate; the
  // triangles inside the boundary are its pieces. Constraints that cross
  // (CGAL throws), points that meet, or a count of triangles that is not
  // the boundary's: Declined.
  void cutFace(int s, std::uint32_t f) {
    struct VertexInfo {
      Id id = 0;
      int ring = -1;  // its place on the boundary, or -1 inside
    };
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
    using Fb =
        CGAL::Triangulation_face_base_with_info_2<bool, K,
                                                  CGAL::Constrained_triangulation_face_base_2<K>>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt =
        CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

    const Triangle& t = ops_[s].corners[f];
    const auto normal = CGAL::cross_product(at(t[1]) - at(t[0]), at(t[2]) - at(t[0]));
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
    // Dropping the axis keeps the orientation for the next two in cyclic
    // order when the normal points along it.
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const bool flipped = normal[axis] < 0.0;
    auto flat = [&](Id id) { return K::Point_2(at(id)[u], at(id)[v]); };

    const std::vector<Id> ring = boundaryOf(s, f);
    const std::vector<Id>& inner = facePoints_[s][f];
    const int n = int(ring.size());
    Cdt cdt;
    std::unordered_map<Id, Cdt::Vertex_handle> handle;
    auto insert = [&](Id id, int place) {
      auto vh = cdt.insert(flat(id));
      if (vh->info().ring != -1 || !handle.emplace(id, vh).second) throw Declined{};
      vh->info() = {id, place};
      if (place == -1) vh->info().ring = -2;  // inserted, inside
    };
    try {
      for (int i = 0; i < n; ++i) insert(ring[i], i);
      for (Id id : inner) insert(id, -1);
      if (cdt.number_of_vertices() != handle.size()) throw Declined{};
      for (int i = 0; i < n; ++i) cdt.insert_constraint(handle[ring[i]], handle[ring[(i + 1) % n]]);
      for (const auto& [a, b] : faceSegments_[s][f]) {
        auto ia = handle.find(a), ib = handle.find(b);
        if (ia == handle.end() || ib == handle.end()) throw Declined{};
        cdt.insert_constraint(ia->second, ib->second);
      }
    } catch (const Declined&) {
      throw;
    } catch (const std::exception&) {
      throw Declined{};  // constraints that cross
    }
    if (cdt.number_of_vertices() != handle.size()) throw Declined{};
    // The faces outside the boundary: reached from the infinite face
    // without crossing a boundary edge.
    auto onRing = [&](Cdt::Face_handle face, int i) {
      const int a = face->vertex(Cdt::cw(i))->info().ring,
                b = face->vertex(Cdt::ccw(i))->info().ring;
      return a >= 0 && b >= 0 && ((a + 1) % n == b || (b + 1) % n == a);
    };
    for (auto face : cdt.all_face_handles()) face->info() = false;
    std::vector<Cdt::Face_handle> pending = {cdt.infinite_face()};
    cdt.infinite_face()->info() = true;
    while (!pending.empty()) {
      auto face = pending.back();
      pending.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto next = face->neighbor(i);
        if (next->info() || onRing(face, i)) continue;
        next->info() = true;
        pending.push_back(next);
      }
    }
    // A polygon of n corners with m points inside has n + 2m − 2
    // triangles (Euler's formula).
    std::size_t inside = 0;
    for (auto face : cdt.finite_face_handles()) {
      if (face->info()) continue;
      ++inside;
      Triangle piece{face->vertex(0)->info().id, face->vertex(1)->info().id,
                     face->vertex(2)->info().id};
      if (flipped) std::swap(piece[1], piece[2]);
      pieces_[s].push_back({piece, f});
    }
    if (inside != std::size_t(n) + 2 * inner.size() - 2) throw Declined{};
  }

  // Whether each piece of operand s lies inside the other operand. The
  // pieces form patches, joined across edges that are not segments; across
  // a segment inside and outside swap (general position). A patch that
  // holds the start of a cut edge takes its side from the sign of that
  // edge's end against the crossed face (exact); a shell that has none is
  // tested with one of its corners (CGAL::Side_of_triangle_mesh, exact
  // predicates). Sides that disagree: Declined.
  void classify(int s) {
    const std::vector<Piece>& pieces = pieces_[s];
    const std::size_t count = pieces.size();
    std::vector<std::uint32_t> parent(count);
    for (std::size_t i = 0; i < count; ++i) parent[i] = std::uint32_t(i);
    auto root = [&](std::uint32_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    // Each edge of a closed mesh has two pieces: the pieces' edges sorted
    // by their ends, in pairs.
    struct EdgeUse {
      std::uint64_t key;
      std::uint32_t piece;
      // (The piece breaks ties: an order that parallel_sort makes the
      // same on any number of threads.)
      bool operator<(const EdgeUse& other) const {
        return key != other.key ? key < other.key : piece < other.piece;
      }
    };
    std::vector<EdgeUse> uses(3 * count);
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) {
      for (int k = 0; k < 3; ++k)
        uses[3 * i + k] = {pairKey(pieces[i].corners[k], pieces[i].corners[(k + 1) % 3]),
                           std::uint32_t(i)};
    });
    tbb::parallel_sort(uses.begin(), uses.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> across;
    for (std::size_t i = 0; i < uses.size(); i += 2) {
      const std::uint64_t key = uses[i].key;
      if (i + 1 == uses.size() || uses[i + 1].key != key ||
          (i + 2 < uses.size() && uses[i + 2].key == key))
        throw Declined{};
      // (A segment runs between two crossings, whose ids follow the
      // operands' points.)
      if (Id(key >> 32) >= ops_[1].base + ops_[1].size && segments_.count(key)) {
        across.emplace_back(uses[i].piece, uses[i + 1].piece);
      } else {
        const std::uint32_t a = root(uses[i].piece), b = root(uses[i + 1].piece);
        if (a != b) parent[a] = b;
      }
    }
    auto pieceOn = [&](Id a, Id b) {
      const EdgeUse probe{pairKey(a, b), 0};
      auto it = std::lower_bound(uses.begin(), uses.end(), probe);
      if (it == uses.end() || it->key != probe.key) throw Declined{};
      return it->piece;
    };
    // The patches' graph across segments: each patch's neighbours in the
    // order of the segments, all in one array (from start[patch] on), not
    // a vector for each of the hundreds of thousands of pieces.
    std::vector<std::uint32_t> start(count + 1, 0);
    for (auto& [a, b] : across) {
      a = root(a), b = root(b);
      if (a == b) throw Declined{};
      ++start[a + 1], ++start[b + 1];
    }
    for (std::size_t i = 0; i < count; ++i) start[i + 1] += start[i];
    std::vector<std::uint32_t> neighbours(start[count]);
    std::vector<std::uint32_t> filled(start.begin(), start.end() - 1);
    for (auto [a, b] : across) neighbours[filled[a]++] = b, neighbours[filled[b]++] = a;
    std::vector<signed char> side(count, -1);  // of each patch's root: 1 inside
    std::vector<std::uint32_t> pending;
    auto label = [&](std::uint32_t patch, bool in) {
      if (side[patch] == -1) {
        side[patch] = in;
        pending.push_back(patch);
      } else if (side[patch] != in) {
        throw Declined{};
      }
    };
    auto spread = [&] {
      while (!pending.empty()) {
        const std::uint32_t patch = pending.back();
        pending.pop_back();
        for (std::uint32_t k = start[patch]; k < start[patch + 1]; ++k)
          label(neighbours[k], !side[patch]);
      }
    };
    for (const Crossing& c : crossings_[s]) {
      const auto& list = edgePoints_[s].at(c.edge);
      std::size_t i = 0;
      while (list[i].second != c.point) ++i;
      const bool towardsLow = c.from < otherEnd(c);
      Id next = c.from;
      if (towardsLow && i > 0) next = list[i - 1].second;
      if (!towardsLow && i + 1 < list.size()) next = list[i + 1].second;
      label(root(pieceOn(c.point, next)), c.fromInside);
    }
    spread();
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint32_t patch = root(std::uint32_t(i));
      if (side[patch] != -1) continue;
      const Id corner = pieces[i].corners[0];
      if (corner >= ops_[s].base + ops_[s].size || corner < ops_[s].base)
        continue;  // a crossing: some other piece of the patch has a corner
      const CGAL::Bounded_side where = placeIn(1 - s, at(corner));
      if (where == CGAL::ON_BOUNDARY) throw Declined{};
      label(patch, where == CGAL::ON_BOUNDED_SIDE);
      spread();
    }
    inside_[s].resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const signed char in = side[root(std::uint32_t(i))];
      if (in == -1) throw Declined{};
      inside_[s][i] = in;
    }
  }

  // The other end of a crossing's edge.
  static Id otherEnd(const Crossing& c) {
    const Id a = Id(c.edge >> 32), b = Id(c.edge);
    return a == c.from ? b : a;
  }

  // Where a point lies against operand s, by a copy of it in doubles.
  CGAL::Bounded_side placeIn(int s, const Point& p) {
    using Mesh = CGAL::Surface_mesh<Point>;
    if (!sideTests_[s]) {
      auto mesh = std::make_shared<Mesh>();
      std::vector<Mesh::Vertex_index> vertex(ops_[s].size);
      for (Id v = 0; v < ops_[s].size; ++v) vertex[v] = mesh->add_vertex(at(ops_[s].base + v));
      for (std::uint32_t f : ops_[s].faces) {
        const Triangle& t = ops_[s].corners[f];
        if (mesh->add_face(vertex[t[0] - ops_[s].base], vertex[t[1] - ops_[s].base],
                           vertex[t[2] - ops_[s].base]) == Mesh::null_face())
          throw Declined{};
      }
      sideMeshes_[s] = mesh;
      sideTests_[s] = std::make_shared<CGAL::Side_of_triangle_mesh<Mesh, K>>(*mesh);
    }
    return (*sideTests_[s])(p);
  }

  // The pieces the operation keeps, as a closed, consistently oriented
  // mesh (each directed edge once, and its reverse once), or Declined.
  std::optional<DoubleMesh> assemble(Boolean::Op op) {
    const bool keepInside[2] = {op == Boolean::Op::Intersection, op != Boolean::Op::Union};
    const bool reverse[2] = {false, op == Boolean::Op::Difference};
    std::vector<Triangle> kept;
    std::vector<std::uint32_t> keptTags;
    for (int s = 0; s < 2; ++s)
      for (std::size_t i = 0; i < pieces_[s].size(); ++i) {
        if (bool(inside_[s][i]) != keepInside[s]) continue;
        Triangle t = pieces_[s][i].corners;
        if (reverse[s]) std::swap(t[1], t[2]);
        kept.push_back(t);
        keptTags.push_back(ops_[s].tags[pieces_[s][i].face]);
      }
    // The points the kept pieces use, in the order of their ids.
    constexpr Id kUnused = ~Id(0);
    std::vector<Id> vertex(points_.size(), kUnused);
    for (const Triangle& t : kept)
      for (Id id : t) vertex[id] = 0;
    DoubleMesh out;
    for (Id id = 0; id < points_.size(); ++id)
      if (vertex[id] != kUnused) {
        vertex[id] = Id(out.mesh.points.size());
        const Point& p = points_[id];
        out.mesh.points.emplace_back(p.x(), p.y(), p.z());
      }
    out.mesh.triangles.reserve(kept.size());
    for (const Triangle& t : kept)
      out.mesh.triangles.push_back({vertex[t[0]], vertex[t[1]], vertex[t[2]]});
    out.tags = std::move(keptTags);
    if (!closedManifold(out.mesh)) throw Declined{};
    return out;
  }

  const DoubleMesh* meshes_[2];
  Operand ops_[2];
  std::vector<Point> points_;
  std::unordered_map<EdgeKey, std::vector<std::pair<double, Id>>> edgePoints_[2];
  std::vector<std::vector<std::pair<Id, Id>>> faceSegments_[2];
  std::vector<std::vector<Id>> facePoints_[2];
  std::unordered_set<std::uint64_t> segments_;
  std::vector<Crossing> crossings_[2];
  // The caller's cancel (engine/cancellation.h), read on every thread of
  // the boolean's long steps: finding the crossings, cutting the faces.
  const std::atomic<bool>* cancel_ = cancelFlag();
  std::vector<Piece> pieces_[2];
  std::vector<char> inside_[2];
  std::shared_ptr<CGAL::Surface_mesh<Point>> sideMeshes_[2];
  std::shared_ptr<CGAL::Side_of_triangle_mesh<CGAL::Surface_mesh<Point>, K>> sideTests_[2];
};

}  // namespace

std::optional<DoubleMesh> doubleBoolean(const DoubleMesh& a, const DoubleMesh& b, Boolean::Op op,
                                        DoubleDecline* why) {
  try {
    return DoubleBoolean(a, b).run(op);
  } catch (const Declined& declined) {
    if (why != nullptr) *why = declined.why;
    return std::nullopt;
  }
}

MeshTopology topologyOf(const DoubleMesh& doubles) {
  // A closed mesh of f triangles has 3f/2 edges; every point is used.
  const TriangleMesh& mesh = doubles.mesh;
  MeshTopology topology;
  topology.euler = static_cast<long long>(mesh.points.size()) -
                   static_cast<long long>(mesh.triangles.size()) / 2;
  // The shells: the points joined along the faces' sides (union-find); a
  // 2-manifold's faces around a point are joined across their edges.
  std::vector<std::uint32_t> parent(mesh.points.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = std::uint32_t(i);
  auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[root(t[k])] = root(t[0]);
  for (std::uint32_t v = 0; v < parent.size(); ++v) topology.shells += root(v) == v;
  return topology;
}

}  // namespace csgray::detail
