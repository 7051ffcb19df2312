#include "export/cgal/mesh_boolean.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "engine/boolean.h"
#include "engine/cancellation.h"
#include "engine/instance.h"
#include "engine/primitive.h"
#include "export/aligned_walls.h"
#include "export/cgal/box_pairs.h"
#include "export/cgal/convex_intersection.h"
#include "export/cgal/double_boolean.h"
#include "export/cgal/exact_boolean.h"
#include "export/cgal/glued_caps.h"
#include "export/cgal/glued_union.h"
#include "export/cgal/mesh_validity.h"
#include "export/cgal/rounded_repair.h"
#include "export/cgal/stray_shells.h"
#include "export/collinear_points.h"
#include "export/filled_holes.h"
#include "export/grazed_faces.h"
#include "export/lengthened_cutters.h"
#include "export/merged_sweeps.h"
#include "export/opened_pinches.h"
#include "export/prism_booleans.h"
#include "export/sweeps_apart.h"
#include "export/swept_rims.h"
#include "export/turned_balls.h"
#include "export/upright_cylinders.h"
#include "export/widened_cutters.h"
#include "tessellation/tessellation.h"

namespace csgray::detail {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// How far from the point of a defect a primitive's box may end and the
// error still name it, in tolerances: the point CGAL's self-intersection
// test gives is where two faces cross, which can lie some tolerances from
// the primitive whose face caused it (a groove's flush top, 9 tolerances
// below the crossing of a fillet's faces that it made).
constexpr double kBlameReach = 10.0;
// How far, in tolerances, the repairs after rounding may move the surface,
// and how many rounds of sliver removal they try. A twentieth: where four
// faces of turned boxes almost meet at a point (OpenSCAD writes rotation
// matrices with 6 digits), the corners there lie 1.2e-4 apart, past a
// hundredth of the default tolerance, and rounding folds the faces
// between them.
constexpr double kRepairReach = 0.05;
constexpr int kSliverRounds = 3;
// How far a boolean made in doubles with one operand moved off the other
// (perturbedInDoubles) may have moved its faces, in contact offsets: the
// growth, and a shift of up to a quarter of it on each axis (√3/4 < 1/2).
constexpr double kPerturbedReach = 1.5;
// Below this many faces in both operands a boolean that is not in general
// position is left to CGAL, which then costs a few milliseconds (two
// boxes on one floor: 2 ms) and keeps the result exact; above it CGAL's
// exact constructions on such operands cost tenths of seconds (the last
// union of examples/rounded_box.lua, 6576 + 4100 faces: 0.41 s). A result
// of CGAL's with fewer faces is rounded to doubles where it stays valid
// (roundIfValid), a check that then costs little.
constexpr std::size_t kPerturbedFaces = 500;
// A union whose operand crosses itself inside the other is refused, for
// another order, while the two have at most this many faces (Evaluator).
constexpr std::size_t kSmallCrossing = 5000;
// How far from its crease a point may lie, and its sides' faces from
// their planes, for it to be dropped (dropCollinearPoints), in tolerances:
// a boolean in doubles puts its new points within rounding (10⁻¹⁴ at
// 100 mm) of where they belong, and a millionth of the tolerance is far
// above that and far below anything a printer makes.
constexpr double kCollinearReach = 1e-6;
// The booleans hold each triangle in exact arithmetic, some hundreds of
// bytes: this many are a few GB.
constexpr std::size_t kMaxExportTriangles = 10'000'000;
// How much longer, in tolerances, the last try makes the cylinders a part
// cuts away past each end (export/lengthened_cutters.h): far past the
// rounding that leaves a bore's end a hair off its tube's, and within
// the tolerance.
constexpr double kLengthenedCutters = 0.1;
// What each cylinder of one radius crossing another among the cutters is
// made wider by (export/widened_cutters.h), times its place among them: a
// thousandth of the tolerance keeps a knurl of a hundred cutters within a
// tenth of it.
constexpr double kWidenedCutters = 1e-3;

// The frame the booleans are evaluated in. A part turned as a whole (or
// mirrored) has that turn folded into every primitive's frame, where it is
// rounded: a hole's top and the plate's top face, flush before the turn,
// no longer lie on one plane, and the corefinement leaves slivers that do
// not survive rounding to the file's precision. So the tree is evaluated
// in the frame of its first primitive's rotation: each primitive's frame
// is taken back through that rotation, and its entries, off by rounding
// only, are snapped to a grid of 2⁻³⁰ (a change of about 10⁻⁹, far below
// any tolerance), whose numbers add up exactly, so that faces flush as
// sums of such (the boxes of a Menger sponge) are flush again. But a
// number not in a frame does not move with them: a pocket 1.7 deep, its
// place 2.3 snapped to the grid, is then a hair off a plate's top at 4.
// So where that fails, the part is made once more with the entries put
// back as written instead (written): an entry within 2⁻⁴⁰ of its
// column's largest is 0, and one within rounding (10⁻¹⁴ of it) of a
// number of 12 significant digits is that number, as a script writes
// them; the others go to the grid. The result is turned back at the end.
struct EvaluationFrame {
  glm::dmat3 worldFromEval{1.0};
  glm::dmat3 evalFromWorld{1.0};
  bool identity = true;
  bool exact = false;    // evalFromWorld's entries all 0 or ±1
  bool written = false;  // entries put back as written where they can be

  explicit EvaluationFrame(const Solid& solid) {
    const Solid* first = &solid;
    while (!first->children().empty()) first = first->children()[0].get();
    auto* primitive = dynamic_cast<const Primitive*>(first);
    if (!primitive) return;
    const glm::dmat3 linear(primitive->frame().worldFromObject());
    // Only a rotation or a mirror (orthonormal columns), so that the
    // tolerance means the same in both frames: to 10⁻⁵, since OpenSCAD's
    // .csg files print rotations with six digits (its logo turned so took
    // 44 s to export in the identity frame, 3 s in this one). The inverse,
    // not the transpose, takes that primitive's own frame back to the
    // identity.
    const glm::dmat3 gram = glm::transpose(linear) * linear;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        if (std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)) > 1e-5) return;
    if (linear == glm::dmat3(1.0)) return;
    worldFromEval = linear;
    evalFromWorld = glm::inverse(linear);
    identity = false;
    // A quarter turn or a mirror across the axes' planes (every entry 0 or
    // ±1: a hull of upright cylinders is an extrusion placed so) takes
    // frames back exactly, and they are kept as they are.
    exact = true;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        exact = exact && (evalFromWorld[c][r] == 0.0 || std::abs(evalFromWorld[c][r]) == 1.0);
  }

  // x on the grid of 2⁻³⁰.
  static double snapped(double x) { return std::ldexp(std::nearbyint(std::ldexp(x, 30)), -30); }

  // x as written, from x off by rounding, in a column whose largest entry
  // is `largest`; else snapped.
  static double restored(double x, double largest) {
    if (std::abs(x) <= 0x1p-40 * largest) return 0.0;
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", x);
    const double written = std::strtod(text, nullptr);
    return std::abs(written - x) <= 1e-14 * std::abs(x) ? written : snapped(x);
  }

  Affine evalFrame(const Affine& frame) const {
    glm::dmat4 m = glm::dmat4(evalFromWorld) * frame.worldFromObject();
    if (!exact)
      for (int c = 0; c < 4; ++c) {
        const double largest = std::max({std::abs(m[c][0]), std::abs(m[c][1]), std::abs(m[c][2])});
        for (int r = 0; r < 3; ++r)
          m[c][r] = written ? restored(m[c][r], largest) : snapped(m[c][r]);
      }
    return Affine::fromMatrix(m);
  }
  // Do frames move when taken back (snapped or restored)?
  bool moves() const { return !identity && !exact; }
  Bounds evalBounds(const Bounds& b) const {
    if (identity || b.empty()) return b;
    if (!b.finite()) {
      // An unbounded solid's box (a half-space's): each side of it in the
      // evaluation's frame from the sides it is made of, by interval
      // arithmetic; a side it does not depend on adds nothing.
      Bounds out{dvec3(0.0), dvec3(0.0)};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          const double m = evalFromWorld[c][r];
          if (m == 0.0) continue;
          const double lo = m * b.lo[c], hi = m * b.hi[c];
          out.lo[r] += std::min(lo, hi);
          out.hi[r] += std::max(lo, hi);
        }
      return out;
    }
    Bounds out;
    for (int i = 0; i < 8; ++i)
      out.include(evalFromWorld *
                  dvec3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z));
    return out;
  }
};

// A coordinate as the file stores it (doubles when `stored` is null).
double storedAs(StoredCoordinate stored, double d) { return stored ? stored(d) : d; }

// How a vertex moves so that each of its faces moves by `delta` along its
// normal (outwards for delta > 0): the displacement v solves n·v = delta
// for the unit normals n of its faces in the least-squares sense,
// (Σ n nᵀ + εI) v = delta Σ n. At a box's corner that is the exact offset
// delta·(±1, ±1, ±1); where the faces are nearly parallel (a smooth
// surface) it is delta along their normal, and ε keeps the vertex of an
// edge (two planes) from sliding along it. A vertex whose faces fold back
// on themselves moves ten times delta at most.
template <class Mesh>
dvec3 vertexOffset(const Mesh& mesh, typename Mesh::Vertex_index v, double delta) {
  glm::dmat3 normalMatrix(0.0);
  dvec3 sum(0.0);
  for (auto f : CGAL::faces_around_target(mesh.halfedge(v), mesh)) {
    if (f == Mesh::null_face()) continue;
    auto h = mesh.halfedge(f);
    const dvec3 a = pointOf(mesh, mesh.source(h)), b = pointOf(mesh, mesh.target(h)),
                c = pointOf(mesh, mesh.target(mesh.next(h)));
    dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (!(length > 0.0)) continue;
    n /= length;
    normalMatrix += glm::outerProduct(n, n);
    sum += n;
  }
  if (sum == dvec3(0.0)) return dvec3(0.0);
  const double trace = normalMatrix[0][0] + normalMatrix[1][1] + normalMatrix[2][2];
  normalMatrix += glm::dmat3(1e-6 * trace);
  dvec3 shift = glm::inverse(normalMatrix) * (delta * sum);
  const double reach = glm::length(shift);
  if (!(reach <= 10.0 * std::abs(delta))) shift *= 10.0 * std::abs(delta) / reach;
  return shift;
}

// The faces of a closed mesh moved by delta along their normals
// (vertexOffset) where they come within `near` (the other operand's box):
// a contact is resolved where it is, and the rest of the mesh keeps its
// exact points, so that a later cut flush with a face far from the
// contact takes all of it instead of leaving a sheet delta thick. Those
// points are also moved by `shift`.
template <class Mesh>
void offsetMesh(Mesh& mesh, double delta, const Bounds& near, const dvec3& shift = dvec3(0.0)) {
  std::vector<std::pair<typename Mesh::Vertex_index, dvec3>> moved;
  for (auto v : mesh.vertices()) {
    const dvec3 p = pointOf(mesh, v);
    if (near.contains(p)) moved.emplace_back(v, p + vertexOffset(mesh, v, delta) + shift);
  }
  for (const auto& [v, q] : moved) mesh.point(v) = typename Mesh::Point(q.x, q.y, q.z);
}

// The mesh's vertices within `near` that share their place (to doubles)
// with another: groups of two or more, each in its own vector.
template <class Mesh>
std::vector<std::vector<typename Mesh::Vertex_index>> coincidentVertices(
    const Mesh& mesh, const Bounds& near = Bounds::everything()) {
  std::vector<std::pair<dvec3, typename Mesh::Vertex_index>> order;
  order.reserve(mesh.number_of_vertices());
  for (auto v : mesh.vertices())
    if (const dvec3 p = pointOf(mesh, v); near.contains(p)) order.emplace_back(p, v);
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.x, a.first.y, a.first.z) < std::tie(b.first.x, b.first.y, b.first.z);
  });
  std::vector<std::vector<typename Mesh::Vertex_index>> groups;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && order[j].first == order[i].first) ++j;
    if (j - i > 1) {
      groups.emplace_back();
      for (std::size_t k = i; k < j; ++k) groups.back().push_back(order[k].second);
    }
    i = j;
  }
  return groups;
}

// Where solids touch at a point, CGAL's boolean keeps the mesh a 2-manifold
// by giving each of them a vertex of its own there, at one place, which the
// validity check rightly finds touching. Each such vertex is moved by delta
// into its own solid, so that the contact becomes a gap of about 2·delta.
// Where instead the empty sides touch (a countersink's tip on the plate's
// far face, two cutters corner to corner), the vertices' faces are the two
// sides of a wall of no thickness: moved into the solid they would cross,
// so each moves out of it, and the wall becomes about 2·delta thick. A
// vertex's faces face the others' across a gap when their mean outward
// normal points towards the others' neighbours. The moved points are
// rounded as the file will store them. Returns how many were moved.
template <class Mesh>
std::size_t separateCoincidentVertices(Mesh& mesh, double delta, StoredCoordinate stored) {
  std::vector<std::pair<typename Mesh::Vertex_index, dvec3>> moved;
  for (const auto& group : coincidentVertices(mesh)) {
    // Each vertex's faces' mean outward normal, and its neighbours' mean.
    std::vector<dvec3> normals, middles;
    for (auto v : group) {
      dvec3 normal(0.0), middle(0.0);
      int count = 0;
      for (auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
        middle += pointOf(mesh, mesh.source(h));
        ++count;
        if (mesh.face(h) == Mesh::null_face()) continue;
        const auto f = mesh.halfedge(mesh.face(h));
        const dvec3 a = pointOf(mesh, mesh.source(f)), b = pointOf(mesh, mesh.target(f)),
                    c = pointOf(mesh, mesh.target(mesh.next(f)));
        const dvec3 n = glm::cross(b - a, c - a);
        if (const double length = glm::length(n); length > 0.0) normal += n / length;
      }
      normals.push_back(normal);
      middles.push_back(count > 0 ? middle / double(count) : pointOf(mesh, v));
    }
    for (std::size_t i = 0; i < group.size(); ++i) {
      double facing = 0.0;
      for (std::size_t j = 0; j < group.size(); ++j)
        if (j != i) facing += glm::dot(normals[i], middles[j] - middles[i]);
      const double by = facing < 0.0 ? delta : -delta;
      moved.emplace_back(group[i], pointOf(mesh, group[i]) + vertexOffset(mesh, group[i], by));
    }
  }
  for (auto& [v, q] : moved)
    mesh.point(v) =
        typename Mesh::Point(storedAs(stored, q.x), storedAs(stored, q.y), storedAs(stored, q.z));
  return moved.size();
}

// A solid as `csgray check` names it: its kind and the script line that
// made it.
std::string describe(const Solid* solid) {
  if (solid == nullptr) return "an operand";
  const std::string line = solid->origin().text();
  return line.empty() ? solid->kind() : solid->kind() + " (" + line + ")";
}

// What booleanInProgress() returns.
char inProgress[600] = "the booleans";
void setBooleanInProgress(const std::string& text) {
  std::snprintf(inProgress, sizeof inProgress, "%s", text.c_str());
}

// The primitives of the part whose boxes (grown by the tolerance) hold p,
// the first four by their script lines, or else the one whose box is
// nearest: who to look at when the mesh fails near p.
std::string primitivesNear(const Solid& solid, const dvec3& p, double tolerance) {
  std::vector<std::string> names;
  std::size_t count = 0;
  const Solid* nearest = nullptr;
  double nearestDistance = kInfinity;
  std::vector<const Solid*> pending = {&solid};
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    const Bounds b = s->bounds();
    if (b.empty()) continue;
    if (dynamic_cast<const Primitive*>(s) == nullptr) {
      for (const SolidPtr& child : s->children()) pending.push_back(child.get());
      continue;
    }
    const double distance = glm::length(glm::max(glm::max(b.lo - p, p - b.hi), dvec3(0.0)));
    if (distance < nearestDistance) nearestDistance = distance, nearest = s;
    if (distance <= tolerance && ++count <= 4) names.push_back(describe(s));
  }
  if (count == 0 && nearest != nullptr) names.push_back(describe(nearest));
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  if (count > names.size()) text += " (" + std::to_string(count - names.size()) + " more)";
  return text;
}

// The point a defect of meshDefect names: its last "(x, y, z)".
bool defectPoint(const std::string& defect, dvec3& p) {
  const std::size_t open = defect.rfind('(');
  return open != std::string::npos &&
         std::sscanf(defect.c_str() + open, "(%lf, %lf, %lf)", &p.x, &p.y, &p.z) == 3;
}

// The order in which the evaluator meets operands, and whether it refuses
// a boolean of an operand that touches itself where the other's surface
// runs (meshOfSolid).
// Why an order's booleans were refused (Evaluator::corefine): a corner
// where two solids touch on the other operand's surface, or an operand of
// a union that crosses itself inside the other.
enum class Refusal { None, Pinch, Crossing };

struct EvaluationOrder {
  bool reversed = false;  // each union's operands, and a difference's cutters, last to first
  bool refusePinches = true;
  bool doubles = true;  // each boolean tried in doubles first (double_boolean.h)
  // Not 0: each union's operands, and a difference's cutters, in an order
  // shuffled by this seed (after `reversed`), for a last try.
  unsigned shuffle = 0;
  // A boolean in doubles that declines for want of general position tried
  // again with one operand moved off the other (perturbedInDoubles).
  bool perturb = true;
  // The frames of a part turned as a whole put back as written, not
  // snapped (EvaluationFrame::written), for a last try.
  bool written = false;

  template <class T>
  void arrange(std::vector<T>& items) const {
    if (reversed) std::reverse(items.begin(), items.end());
    if (shuffle == 0) return;
    // Fisher–Yates with the standard's fully specified engine, so that a
    // part exports the same on every platform (std::shuffle is not).
    std::mt19937 random(shuffle);
    for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[random() % i]);
  }
};

// Evaluates the tree with exact constructions (Epeck): a corefinement's new
// points are exact, so the next boolean in a chain sees them where they
// are (CGAL's manual, PMP, "Corefinement and Boolean Operations": with
// inexact constructions a chained result may self-intersect, and CGAL's
// face triangulation may then crash). Measured on plate(8), Epick was no
// faster: CGAL computes the intersection points exactly either way.
// Pieces made in doubles (primitives, booleans in doubles) stay in doubles
// (double_mesh.h) until CGAL needs them: building CGAL's mesh face by face
// cost plate(32) more than its booleans in doubles.
class Evaluator {
 public:
  using Mesh = ExactMesh;
  using K = CGAL::Epeck;
  using Face = typename Mesh::Face_index;
  using Vertex = typename Mesh::Vertex_index;

  // Part of the tree, evaluated: a mesh and the box of its points. The
  // mesh is held in doubles while every step that made it was made so (a
  // primitive's tessellation, booleans in doubles, joins of such pieces),
  // else as CGAL's exact mesh; exact() makes the one from the other.
  struct Piece {
    std::optional<DoubleMesh> doubles;
    Mesh mesh;  // when doubles holds nothing
    Bounds box;
    const Solid* origin = nullptr;  // the primitive or boolean it was made by
    std::size_t shape = 0;  // of a primitive's mesh: a hash of its points; 0 after a boolean
    // How far a contact's offset (corefine) moved some of its faces, at
    // most: 0 while every face is where the model puts it; and how far it
    // moved some into the solid (an intersection's operand shrunk, a
    // cutter's faces in a difference grown), at most.
    double grown = 0.0;
    double shrunk = 0.0;
    Bounds shrunkNear;  // where those faces moved in lie; empty if none did
    std::size_t faces() const {
      return doubles ? doubles->mesh.size() : std::size_t(mesh.number_of_faces());
    }
    bool empty() const { return faces() == 0; }
  };

  // order: the order it meets operands in, and whether it refuses to cut
  // where an operand touches itself (see meshOfSolid).
  // stored: how the file rounds a coordinate (null: not at all).
  Evaluator(double tolerance, const EvaluationFrame& frame, MeshBooleanStats& stats,
            const EvaluationOrder& order, StoredCoordinate stored)
      : tolerance_(tolerance), frame_(frame), stats_(stats), order_(order), stored_(stored) {}

  Refusal refusal() const { return refusal_; }

  // A mesh M with M ∩ region = solid ∩ region; M may reach past the region
  // (an unbounded primitive is meshed within a larger box), which the
  // operations above it cut away.
  Piece evaluate(const Solid& solid, const Bounds& outer) {
    stopIfCancelled();
    // The first call is the part's: its cylinders, for its extrusions.
    if (!rims_)
      rims_.emplace(solid, [this](const Primitive& p) {
        auto placed = placedPrimitive(p);
        return placed ? placed : std::static_pointer_cast<const Primitive>(p.shared_from_this());
      });
    const Bounds region = outer.intersected(frame_.evalBounds(solid.bounds()));
    if (region.empty()) return {};
    if (auto* primitive = dynamic_cast<const Primitive*>(&solid)) {
      Piece piece = leaf(*primitive, region);
      piece.origin = &solid;
      return piece;
    }
    Piece piece = combine(solid, region);
    if (piece.origin != nullptr) piece.origin = &solid;
    return piece;
  }

  // The pieces of a boolean's operands, combined.
  Piece combine(const Solid& solid, const Bounds& region) {
    auto* node = dynamic_cast<const Boolean*>(&solid);
    if (!node) throw std::logic_error("meshOfSolid: unknown solid " + solid.kind());
    std::span<const SolidPtr> operands = node->children();
    switch (node->op()) {
      case Boolean::Op::Union: {
        std::vector<Piece> pieces = evaluateAll(operands, region);
        order_.arrange(pieces);
        return unite(std::move(pieces));
      }
      case Boolean::Op::Intersection: {
        if (std::optional<Piece> convex = convexIntersection(operands, region)) {
          if (!convex->empty()) convex->origin = &solid;
          return std::move(*convex);
        }
        std::vector<Piece> pieces;
        for (const SolidPtr& s : operands) {
          pieces.push_back(evaluate(*s, region));
          if (pieces.back().empty()) return {};
        }
        dropRepeats(pieces);
        return balanced(std::move(pieces), Boolean::Op::Intersection);
      }
      case Boolean::Op::Difference: {
        Piece minuend = evaluate(*operands[0], region);
        if (minuend.empty()) return minuend;
        // Whatever is cut away is cut from the minuend's mesh, which may
        // reach past the region: the cutters are meshed over all of it.
        std::vector<Piece> cutters = evaluateAll(operands.subspan(1), minuend.box);
        clearGrazedCutters(*operands[0], operands.subspan(1), cutters, minuend);
        order_.arrange(cutters);
        const bool primitives =
            cutters.size() > 1 && std::all_of(cutters.begin(), cutters.end(),
                                              [](const Piece& c) { return c.shape != 0; });
        const std::size_t byCgal = stats_.corefinements - stats_.inDoubles;
        Piece cut = unite(std::move(cutters));
        // Cutters that overlap are united first. Where their union is not
        // in general position (two equal bores that cross) and too small
        // to be moved off (kPerturbedFaces), CGAL makes it, exactly, and
        // the cut of the minuend by that exact mesh then goes to CGAL too,
        // however large (a ball less three crossing bores: 0.58 s, against
        // 0.16 s). The cutters are then cut away one by one instead, each
        // a boolean of the large minuend and one cutter, which the
        // booleans in doubles take (moving the cutter where it touches the
        // wall of another). Taken only if every cut is made so (else the
        // union is cut away as before), and only for cutters that are
        // primitives, cheap to mesh again (another cutter's booleans would
        // be made twice).
        if (order_.doubles && primitives && minuend.doubles &&
            stats_.corefinements - stats_.inDoubles > byCgal) {
          const MeshBooleanStats before = stats_;
          std::vector<Piece> each = evaluateAll(operands.subspan(1), minuend.box);
          clearGrazedCutters(*operands[0], operands.subspan(1), each, minuend);
          order_.arrange(each);
          Piece oneByOne = minuend;
          doublesOnly_ = true;
          declinedInDoubles_ = false;
          for (Piece& one : each) {
            cutAway(oneByOne, one);
            if (declinedInDoubles_) break;
          }
          doublesOnly_ = false;
          if (!declinedInDoubles_) return oneByOne;
          stats_ = before;
        }
        cutAway(minuend, cut);
        return minuend;
      }
    }
    return {};
  }

  std::vector<MaterialPtr> materials;

 private:
  // While set, a boolean that the booleans in doubles decline is not made
  // by CGAL: declinedInDoubles_ says so, and the operands are left as
  // they were, or as far as the booleans in doubles got.
  bool doublesOnly_ = false;
  bool declinedInDoubles_ = false;

  // minuend less cut.
  void cutAway(Piece& minuend, Piece& cut) {
    if (cut.empty() || !minuend.box.overlaps(cut.box)) return;
    // A contact's offset moved some of the minuend's faces off the
    // model's: a cut flush with such a face (a grid cell cut out next to
    // two cells that touch along an edge) would leave a sheet of that
    // thickness, so the cutter grows past it. The same where the offset
    // moved the cutter's own faces in (an intersection's operand shrunk
    // off a point contact: a paraboloid clipped by a box its vertex
    // touches, the box's top then flush with the minuend's).
    if (const double moved = std::max(minuend.grown, cut.shrunk); moved > 0.0) {
      const dvec3 reach(tolerance_);
      offsetMesh(exact(cut), moved + kContactOffset * tolerance_,
                 {minuend.box.lo - reach, minuend.box.hi + reach});
      cut.shape = 0;
    }
    corefine(minuend, cut, Boolean::Op::Difference);
  }

  // Each flat cutter (a box, a half-space, a convex polyhedron) whose
  // faces the minuend only grazes, made again with those faces moved
  // clear of it (export/grazed_faces.h); and each straight extrusion
  // whose caps it only grazes (letters engraved from a rod's tangent
  // plane), with those caps moved. cutters[i] is operands[i]'s;
  // minuendSolid is the exact solid whose mesh is minuend.
  void clearGrazedCutters(const Solid& minuendSolid, std::span<const SolidPtr> operands,
                          std::vector<Piece>& cutters, const Piece& minuend) {
    std::optional<TriangleMesh> exactMinuend;  // in doubles, made once if needed
    std::optional<GrazeTest> test;
    auto grazeTest = [&]() -> const GrazeTest& {
      if (!test) {
        if (!minuend.doubles) exactMinuend = trianglesOf(minuend.mesh, true);
        test.emplace(
            minuend.doubles ? minuend.doubles->mesh : *exactMinuend, tolerance_,
            [&](const dvec3& p) { return minuendSolid.contains(frame_.worldFromEval * p); });
      }
      return *test;
    };
    for (std::size_t i = 0; i < operands.size(); ++i) {
      auto* primitive = dynamic_cast<const Primitive*>(operands[i].get());
      Piece& cutter = cutters[i];
      if (!primitive || cutter.empty() || !cutter.box.overlaps(minuend.box)) continue;
      const Affine frame = frame_.evalFrame(primitive->frame());
      if (std::optional<std::vector<BoundingPlane>> planes = boundingPlanes(*primitive, frame)) {
        if (!grazeTest().clearGrazedFaces(*planes, cutter.box)) continue;
        // The moved faces stay within twice the tolerance of the old.
        const dvec3 margin(0.01 * glm::length(cutter.box.size()) + 2.0 * tolerance_);
        cutter =
            pieceOf(convexPolytopeMesh(*planes, {cutter.box.lo - margin, cutter.box.hi + margin}),
                    tagOf(primitive->material()), primitive->kind());
      } else if (std::optional<std::vector<BoundingPlane>> caps = prismCapPlanes(*primitive, frame);
                 caps && cutter.doubles) {
        const std::vector<BoundingPlane> before = *caps;
        if (!grazeTest().clearGrazedFaces(*caps, cutter.box)) continue;
        // A cap moves out along its normal, its points with it: the sides
        // stay flat, as each of their top edges moves by one vector.
        TriangleMesh moved = cutter.doubles->mesh;
        bool any = false;
        for (int cap = 0; cap < 2; ++cap) {
          const BoundingPlane& was = before[cap];
          const double by = (*caps)[cap].offset - was.offset;
          if (!(by > 0.0)) continue;
          const double on = 1e-9 * glm::length(cutter.box.size());
          for (dvec3& p : moved.points)
            if (std::abs(glm::dot(was.normal, p) - was.offset) <= on) p += by * was.normal;
          any = true;
        }
        if (!any) continue;
        cutter = pieceOf(std::move(moved), tagOf(primitive->material()), primitive->kind());
      } else {
        continue;
      }
      cutter.origin = primitive;
      ++stats_.grazes;
    }
  }

  std::uint32_t tagOf(const MaterialPtr& material) {
    auto [it, added] = tags_.try_emplace(material.get(), std::uint32_t(materials.size()));
    if (added) materials.push_back(material);
    return it->second;
  }

  Piece leaf(const Primitive& primitive, const Bounds& region) {
    ++stats_.primitives;
    TriangleMesh triangles = tessellation(primitive, region);
    countTriangles(triangles.size());
    refusePinched(triangles, primitive);
    return pieceOf(std::move(triangles), tagOf(primitive.material()), primitive.kind());
  }

  // A sweep of a region that touches itself at a point is pinched along a
  // line (TriangleMesh::pinched), and CGAL's corefinement, whose operands
  // must not touch themselves, ran without end on one (a bowtie polygon's
  // sweep beside a box touching its corners). Such a sweep fails here
  // instead, before any boolean, and the last tries (meshOfFlatPart) take
  // it apart or open it there.
  static void refusePinched(const TriangleMesh& triangles, const Primitive& primitive) {
    if (triangles.pinched)
      throw std::runtime_error(primitive.kind() + ": its region touches itself at a point");
  }

  // The operands' pieces, in their order, as evaluate makes them one by
  // one. The primitives among them are tessellated on all threads first
  // (their triangles are plain doubles, each apart from the others); the
  // rest is done here in the operands' order: what the evaluation counts
  // and names (the primitives, the triangles against the limit, the
  // materials' tags, the first error), so that the result does not depend
  // on the threads, and the exact meshes. (Made on all threads too, those
  // meshes' points lay scattered in memory: the Sierpinski tetrahedron's
  // weld of 4096 pieces then took a fifth more time.)
  std::vector<Piece> evaluateAll(std::span<const SolidPtr> operands, const Bounds& region) {
    const std::size_t n = operands.size();
    std::vector<const Primitive*> primitives(n, nullptr);
    std::vector<Bounds> regions(n);
    for (std::size_t i = 0; i < n; ++i)
      if (auto* primitive = dynamic_cast<const Primitive*>(operands[i].get())) {
        primitives[i] = primitive;
        regions[i] = region.intersected(frame_.evalBounds(primitive->bounds()));
      }
    auto tessellated = [&](std::size_t i) { return primitives[i] && !regions[i].empty(); };
    std::vector<TriangleMesh> triangles(n);
    std::vector<std::exception_ptr> failed(n);
    const std::atomic<bool>* cancel = cancelFlag();  // (read on TBB's threads too)
    auto tessellate = [&](std::size_t i) {
      if (!tessellated(i)) return;
      try {
        stopIfCancelled(cancel);
        triangles[i] = tessellation(*primitives[i], regions[i]);
        refusePinched(triangles[i], *primitives[i]);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    };
    // A few primitives are tessellated here: starting TBB's scheduler
    // (about half a millisecond, as in roundedFaces) would cost more.
    constexpr std::size_t kFewOperands = 8;
    if (n < kFewOperands)
      for (std::size_t i = 0; i < n; ++i) tessellate(i);
    else
      tbb::parallel_for(std::size_t(0), n, tessellate);
    std::vector<Piece> pieces(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!primitives[i]) pieces[i] = evaluate(*operands[i], region);
      if (!tessellated(i)) continue;
      if (failed[i]) std::rethrow_exception(failed[i]);
      ++stats_.primitives;
      countTriangles(triangles[i].size());
      pieces[i] =
          pieceOf(std::move(triangles[i]), tagOf(primitives[i]->material()), primitives[i]->kind());
      pieces[i].origin = primitives[i];
    }
    return pieces;
  }

  // The primitive as it is tessellated: in the evaluation's frame, where
  // a cylinder or cone turned upside down or mirrored is placed the right
  // way up (export/upright_cylinders.h), and a ball turned or mirrored
  // unturned (export/turned_balls.h). Null where that is the primitive as
  // it is.
  std::shared_ptr<const Primitive> placedPrimitive(const Primitive& primitive) const {
    const Affine frame = frame_.identity ? primitive.frame() : frame_.evalFrame(primitive.frame());
    if (auto* cylinder = dynamic_cast<const Cylinder*>(&primitive))
      if (auto upright = uprightCylinder(*cylinder, frame)) return upright;
    if (auto* ball = dynamic_cast<const Sphere*>(&primitive))
      if (auto unturned = unturnedBall(*ball, frame)) return unturned;
    if (frame_.identity) return nullptr;
    return std::dynamic_pointer_cast<const Primitive>(primitive.withFrame(frame));
  }

  // The primitive's triangles within the region, in the evaluation's frame;
  // an extrusion's circles that a cylinder of the part stands on on that
  // cylinder's rim polygon (export/swept_rims.h).
  TriangleMesh tessellation(const Primitive& primitive, const Bounds& region) const {
    const std::shared_ptr<const Primitive> placed = placedPrimitive(primitive);
    const Primitive& shape = placed ? *placed : primitive;
    if (auto* sweep = dynamic_cast<const LinearExtrusion*>(&shape);
        sweep && rims_ && !rims_->empty()) {
      std::vector<CircleRim> rims = rims_->of(*sweep);
      if (!rims.empty()) return sweep->withRims(std::move(rims))->tessellate(tolerance_, region);
    }
    if (auto* cylinder = dynamic_cast<const Cylinder*>(&shape); cylinder && rims_) {
      std::optional<CirclePolygon> polygon =
          rims_->turnedWallPolygon(primitive, *cylinder, tolerance_);
      if (!polygon) polygon = rims_->turnedEndPolygon(*cylinder, tolerance_);
      if (polygon) return cylinder->withPolygon(*polygon)->tessellate(tolerance_, region);
    }
    return shape.tessellate(tolerance_, region);
  }

  // Each primitive keeps within its limit; the whole part within
  // kMaxExportTriangles, checked as each primitive's count is added
  // (before its exact copy, several times the size, is made).
  void countTriangles(std::size_t count) {
    triangles_ += count;
    if (triangles_ > kMaxExportTriangles) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "the part needs more than %zu triangles at a tolerance of %g; give a larger "
                    "tolerance",
                    kMaxExportTriangles, tolerance_);
      throw std::invalid_argument(text);
    }
  }

  // The piece of triangles, in doubles, its faces tagged with one
  // material's tag.
  static Piece pieceOf(TriangleMesh triangles, std::uint32_t tag, const std::string& kind) {
    Piece piece;
    if (triangles.empty()) return piece;
    // (A sweep of a region that touches itself at a point: the export's
    // last tries take it apart or open it there.)
    if (!closedManifold(triangles))
      throw std::runtime_error(kind + ": its tessellation is not a 2-manifold");
    piece.box = triangles.bounds();
    for (const dvec3& p : triangles.points)
      for (double x : {p.x, p.y, p.z})
        piece.shape = piece.shape * 1099511628211u ^ std::hash<double>{}(x);
    piece.doubles.emplace();
    piece.doubles->tags.assign(triangles.size(), tag);
    piece.doubles->mesh = std::move(triangles);
    return piece;
  }

  // The piece's exact mesh, made from its doubles the first time it is
  // needed (and then kept instead of them).
  static Mesh& exact(Piece& piece) {
    if (piece.doubles) {
      piece.mesh = exactOf(*piece.doubles);
      piece.doubles.reset();
    }
    return piece.mesh;
  }

  // An intersection of convex primitives of one material (a box cut by a
  // half-space) as the convex polytope of all their planes, its corners
  // where three planes meet (convex_intersection.h); nothing when an
  // operand is not such a primitive. Closed by the faces of the region
  // grown by a margin where the planes leave it open.
  std::optional<Piece> convexIntersection(std::span<const SolidPtr> operands,
                                          const Bounds& region) {
    std::vector<BoundingPlane> planes;
    const MaterialPtr* material = nullptr;
    for (const SolidPtr& operand : operands) {
      auto* primitive = dynamic_cast<const Primitive*>(operand.get());
      if (primitive == nullptr) return std::nullopt;
      if (material != nullptr && primitive->material() != *material) return std::nullopt;
      material = &primitive->material();
      auto own = boundingPlanes(*primitive, frame_.evalFrame(primitive->frame()));
      if (!own) return std::nullopt;
      planes.insert(planes.end(), own->begin(), own->end());
    }
    if (material == nullptr || !region.finite()) return std::nullopt;
    stats_.primitives += operands.size();
    TriangleMesh triangles = convexPolytopeMesh(planes, regionWithMargin(region, tolerance_));
    countTriangles(triangles.size());
    return pieceOf(std::move(triangles), tagOf(*material), "intersection");
  }

  // What a records of its moved faces after a = a op b, where the boolean
  // itself moved b's faces by up to `moved` (a contact's offset or a
  // perturbation: out of a union, into the result otherwise). A
  // difference turns b's faces inside out: any move of them may be one
  // into the result.
  static void keepMoves(Piece& a, const Piece& b, Boolean::Op op, double moved = 0.0) {
    a.grown = std::max(a.grown, b.grown) + moved;
    const bool difference = op == Boolean::Op::Difference;
    const double bInto = difference ? b.grown : b.shrunk;
    if (bInto > 0.0) a.shrunkNear.include(difference ? b.box : b.shrunkNear);
    if (op != Boolean::Op::Union && moved > 0.0) a.shrunkNear.include(b.box);
    a.shrunk = std::max(a.shrunk, bInto) + (op == Boolean::Op::Union ? 0.0 : moved);
  }

  // A face of one operand of a union that a contact's offset moved into
  // it (a hole cut again by a cutter moved off its wall) stands off an
  // operand flush with it in the model (a pin of the hole's radius), which
  // then stays a shell of its own: that operand grows past the gap, near
  // the moved faces only.
  void closeShrunkGaps(Piece& a, Piece& b) {
    auto growNear = [&](Piece& grows, const Piece& moved) {
      if (!(moved.shrunk > 0.0)) return false;
      const dvec3 reach(tolerance_);
      const Bounds near{moved.shrunkNear.lo - reach, moved.shrunkNear.hi + reach};
      if (!grows.box.overlaps(near)) return false;
      const double by = std::max(a.shrunk, b.shrunk) + kContactOffset * tolerance_;
      offsetMesh(exact(grows), by, near);
      grows.shape = 0;
      grows.grown += by;
      return true;
    };
    if (!growNear(b, a)) growNear(a, b);
  }

  // Adds b's shells to a: their boxes are apart, so no face of one meets
  // the other.
  void join(Piece& a, Piece& b) {
    if (a.doubles && b.doubles) {
      a.doubles->append(*b.doubles);
    } else {
      tagsOf(exact(b));
      exact(a).join(b.mesh);
    }
    a.box.include(b.box);
    a.shape = 0;
    keepMoves(a, b, Boolean::Op::Union);
    ++stats_.merges;
  }

  // For each piece, the earlier pieces (by index, ascending) whose boxes
  // meet its own, each box grown by what meetInUnion grows it by and by
  // twice its hair (hairApart's reach): every pair those two can find.
  std::vector<std::vector<std::uint32_t>> earlierNeighbours(
      const std::vector<Piece>& pieces) const {
    std::vector<FaceBox> boxes;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      if (p.empty()) continue;
      const double by =
          (p.shrunk > 0.0 ? p.shrunk + kContactOffset * tolerance_ : 0.0) + 2.0 * hair(p.box);
      FaceBox box{{}, {}, std::uint32_t(i)};
      for (int d = 0; d < 3; ++d) {
        box.lo[d] = p.box.lo[d] - by;
        box.hi[d] = p.box.hi[d] + by;
      }
      boxes.push_back(box);
    }
    std::mutex lock;
    std::vector<std::vector<std::uint32_t>> earlier(pieces.size());
    const std::atomic<bool>* cancel = cancelFlag();
    forEachMeetingPair(boxes, [&](std::uint32_t a, std::uint32_t b) {
      stopIfCancelled(cancel);
      std::lock_guard guard(lock);
      earlier[std::max(a, b)].push_back(std::min(a, b));
    });
    for (auto& list : earlier) std::sort(list.begin(), list.end());
    return earlier;
  }

  // Pieces whose boxes are pairwise apart are joined into one group; the
  // groups are then united pairwise in a balanced order, so that no mesh
  // is corefined more than log₂(groups) times. (Boxes are closed,
  // Bounds::overlaps: operands that touch are corefined, not joined.)
  Piece unite(std::vector<Piece> pieces) {
    dropRepeats(pieces);
    closeHairGaps(pieces);
    alignWalls(pieces);
    glueStacked(pieces);
    glueLegsOnTurns(pieces);
    // Each piece joins the first group none of whose members it meets in
    // the union. The members it may meet, or lie a hair from, are found
    // among its neighbours: the earlier pieces whose boxes, grown by what
    // meetInUnion and hairApart allow, meet its own (a scan of every
    // group's members for each piece was n² for a union of n parts that
    // touch, 5·10¹¹ for the million tetrahedra of a Sierpinski tetrahedron of
    // level 10).
    const std::vector<std::vector<std::uint32_t>> earlier = earlierNeighbours(pieces);
    std::vector<std::vector<std::size_t>> groups;
    std::vector<std::size_t> groupOf(pieces.size(), 0);
    std::vector<std::size_t> blocked;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      Piece& piece = pieces[i];
      if (piece.empty()) continue;
      blocked.clear();
      for (const std::uint32_t q : earlier[i])
        if (meetInUnion(pieces[q], piece)) blocked.push_back(groupOf[q]);
      std::sort(blocked.begin(), blocked.end());
      std::size_t group = 0;
      for (const std::size_t b : blocked)
        if (b == group) ++group;
      if (group == groups.size()) groups.emplace_back();
      // Boxes apart by a hair: corners a hair apart are made one place,
      // which the end resolves as a contact (separateCoincidentVertices).
      // Each member on its own, before the group is joined: no point of
      // the piece lies in another member, whose box is apart from its box,
      // and the inside tests then build their trees over one member's
      // faces, not over all the group's so far (a Sierpinski tetrahedron's
      // 4 096 parts, touching at corners, took 11 s in those trees).
      for (const std::uint32_t q : earlier[i])
        if (groupOf[q] == group)
          weldNearVertices(pieces[q], piece, hairApart(pieces[q].box, piece.box));
      groupOf[i] = group;
      groups[group].push_back(i);
    }
    std::vector<Piece> joined;
    for (const std::vector<std::size_t>& members : groups) {
      for (std::size_t k = 1; k < members.size(); ++k) join(pieces[members[0]], pieces[members[k]]);
      joined.push_back(std::move(pieces[members[0]]));
    }
    return balanced(std::move(joined), Boolean::Op::Union);
  }

  // Operands that stand on each other on the same faces are glued first
  // (glueAcrossPlane): grouped by their boxes they would be corefined as
  // parts of larger meshes (a stack's even and odd frustums). Candidates
  // are the pairs where one box's top face is in the plane of another's
  // bottom face, on any axis, looked up by that coordinate. A glue costs
  // the size of both meshes, so it goes in rounds in which each piece is
  // glued once at most and tried a few times, as a balanced tree would:
  // a stack of n costs n log n, not n², and a grid of cubes, whose merged
  // blocks soon stop matching, no more than without gluing (50 × 50
  // cubes: 4.1 s glued one by one, 2.0 s in rounds, 2.0 s before gluing
  // was tried). A piece glued into another leaves an empty piece behind.
  void glueStacked(std::vector<Piece>& pieces) {
    constexpr int kTriesPerRound = 6;  // a box's faces
    for (bool glued = true; glued;) {
      glued = false;
      std::unordered_multimap<double, std::size_t> byTop[3];
      for (std::size_t i = 0; i < pieces.size(); ++i)
        if (!pieces[i].empty())
          for (int k = 0; k < 3; ++k) byTop[k].emplace(pieces[i].box.hi[k], i);
      std::vector<bool> used(pieces.size(), false);
      std::vector<int> tries(pieces.size(), 0);
      for (std::size_t j = 0; j < pieces.size(); ++j) {
        for (int k = 0; k < 3 && !pieces[j].empty() && !used[j]; ++k) {
          auto [first, last] = byTop[k].equal_range(pieces[j].box.lo[k]);
          for (auto it = first; it != last && tries[j] < kTriesPerRound;) {
            const std::size_t i = it->second;
            if (i == j) {
              ++it;
              continue;
            }
            // A piece this round has no more use for leaves the table, or
            // each of many boxes on one plane (the million tetrahedra of a
            // Sierpinski tetrahedron of level 10 stand on 1 024) walks past
            // all the others there.
            if (used[i] || pieces[i].empty() || tries[i] >= kTriesPerRound) {
              it = byTop[k].erase(it);
              continue;
            }
            ++it;
            ++tries[i];
            ++tries[j];
            if (!glue(pieces[i], pieces[j])) continue;
            ++stats_.glued;
            pieces[i].box.include(pieces[j].box);
            pieces[i].shape = 0;
            keepMoves(pieces[i], pieces[j], Boolean::Op::Union);
            pieces[j] = Piece{};
            used[i] = used[j] = glued = true;
            break;
          }
        }
      }
    }
  }

  // A cylinder standing on an end face of a turn that is not whole, on
  // the turn's own polygon (a pipe's leg on its bend: turnedEndPolygon),
  // is glued to the piece that holds the turn there (glueAtSharedCap):
  // the face may lie in any plane, and the two meshes' points on it
  // differ in their last bits (in a part turned as a whole, by the grid
  // of 2⁻³⁰ its frames are snapped to), which a corefinement would leave
  // as slivers along the walls.
  void glueLegsOnTurns(std::vector<Piece>& pieces) {
    for (Piece& leg : pieces) {
      if (!onTurnsEnd(leg)) continue;
      std::optional<DoubleMesh> legMade = leg.doubles ? std::nullopt : doublesOf(leg.mesh);
      const DoubleMesh* b = leg.doubles ? &*leg.doubles : legMade ? &*legMade : nullptr;
      for (Piece& turn : pieces) {
        if (!b || &turn == &leg || turn.empty() || !turn.box.overlaps(leg.box)) continue;
        // (Pieces made exact by the steps before may still hold doubles.)
        std::optional<DoubleMesh> made = turn.doubles ? std::nullopt : doublesOf(turn.mesh);
        DoubleMesh* a = turn.doubles ? &*turn.doubles : made ? &*made : nullptr;
        if (!a) continue;
        const dvec3 far = glm::max(glm::abs(turn.box.lo), glm::abs(turn.box.hi)) +
                          glm::max(glm::abs(leg.box.lo), glm::abs(leg.box.hi));
        const double reach = 1e-9 * std::max({far.x, far.y, far.z});
        if (!glueAtSharedCap(*a, *b, turn.box, leg.box, reach)) continue;
        if (made) {
          turn.doubles = std::move(made);
          turn.mesh = Mesh();
        }
        ++stats_.glued;
        turn.box.include(leg.box);
        turn.shape = 0;
        keepMoves(turn, leg, Boolean::Op::Union);
        leg = Piece{};
        break;
      }
    }
  }

  // Is the piece a cylinder's that took a turn's polygon for its end?
  bool onTurnsEnd(const Piece& piece) const {
    auto* primitive = dynamic_cast<const Primitive*>(piece.origin);
    if (!primitive || !rims_ || !dynamic_cast<const Cylinder*>(primitive)) return false;
    const std::shared_ptr<const Primitive> placed = placedPrimitive(*primitive);
    auto* cylinder = dynamic_cast<const Cylinder*>(placed ? placed.get() : primitive);
    return cylinder && rims_->turnedEndPolygon(*cylinder, tolerance_).has_value();
  }

  // Do the pieces' boxes meet, each grown back by what a contact's offset
  // shrank it? (The plate of rounded_box ∩ box, whose box was shrunk off
  // the rounded box's side it shared, is then a hair below letters that
  // stand on its top: joined without a boolean, they stayed shells of
  // their own.) A union then corefines them, and closeShrunkGaps closes
  // the gap.
  bool meetInUnion(const Piece& a, const Piece& b) const {
    auto grown = [&](const Piece& p) {
      const dvec3 by(p.shrunk > 0.0 ? p.shrunk + kContactOffset * tolerance_ : 0.0);
      return Bounds{p.box.lo - by, p.box.hi + by};
    };
    return grown(a).overlaps(grown(b));
  }

  Piece balanced(std::vector<Piece> pieces, Boolean::Op op) {
    if (pieces.empty()) return {};
    while (pieces.size() > 1) {
      std::vector<Piece> next;
      for (std::size_t i = 0; i + 1 < pieces.size(); i += 2) {
        Piece& a = pieces[i];
        Piece& b = pieces[i + 1];
        if (op == Boolean::Op::Union ? !meetInUnion(a, b) : !a.box.overlaps(b.box)) {
          if (op == Boolean::Op::Intersection) return {};
          weldNearVertices(a, b, hairApart(a.box, b.box));
          join(a, b);
        } else {
          corefine(a, b, op);
          if (a.empty() && op == Boolean::Op::Intersection) return {};
        }
        next.push_back(std::move(a));
      }
      if (pieces.size() % 2) next.push_back(std::move(pieces.back()));
      pieces = std::move(next);
    }
    return std::move(pieces[0]);
  }

  // Solids stacked face to face (glueAcrossPlane), their exact meshes made
  // only where their boxes meet in a plane.
  static bool glue(Piece& a, Piece& b) {
    if (!meetInPlane(a.box, b.box)) return false;
    return glueAcrossPlane(exact(a), exact(b), a.box, b.box);
  }

  // A piece's exact mesh, made anew from its doubles if it holds them.
  static Mesh asExact(const Piece& piece) {
    return piece.doubles ? exactOf(*piece.doubles) : piece.mesh;
  }

  // A union or intersection of a primitive with itself is that primitive,
  // but CGAL's corefinement of two equal meshes handles every pair of
  // coincident triangles (two equal spheres: 0.4 s for 320 triangles; a
  // grid of parts that repeats some: 17 s against 0.03 s), so a piece whose
  // mesh is another's, point for point, is dropped.
  // (The kept pieces are looked up by their hash: a scan of all kept for
  // each piece was 5·10¹¹ comparisons for the million tetrahedra of a
  // Sierpinski tetrahedron of level 10.)
  static void dropRepeats(std::vector<Piece>& pieces) {
    std::vector<Piece> kept;
    std::unordered_multimap<std::size_t, std::size_t> byShape;
    for (Piece& piece : pieces) {
      if (piece.shape != 0) {
        auto [first, last] = byShape.equal_range(piece.shape);
        if (std::any_of(first, last,
                        [&](const auto& k) { return sameMesh(kept[k.second], piece); }))
          continue;
        byShape.emplace(piece.shape, kept.size());
      }
      kept.push_back(std::move(piece));
    }
    pieces = std::move(kept);
  }

  static bool sameMesh(const Piece& p, const Piece& q) {
    if (p.doubles && q.doubles)
      return p.doubles->mesh.points == q.doubles->mesh.points &&
             p.doubles->mesh.triangles == q.doubles->mesh.triangles;
    if (p.doubles || q.doubles) return sameMesh(asExact(p), asExact(q));
    return sameMesh(p.mesh, q.mesh);
  }

  static bool sameMesh(const Mesh& a, const Mesh& b) {
    if (a.number_of_vertices() != b.number_of_vertices() ||
        a.number_of_faces() != b.number_of_faces())
      return false;
    for (auto [v, w] = std::pair(a.vertices().begin(), b.vertices().begin());
         v != a.vertices().end(); ++v, ++w)
      if (*v != *w || a.point(*v) != b.point(*w)) return false;
    for (auto [f, g] = std::pair(a.faces().begin(), b.faces().begin()); f != a.faces().end();
         ++f, ++g) {
      auto h = a.halfedge(*f), k = b.halfedge(*g);
      for (int corner = 0; corner < 3; ++corner, h = a.next(h), k = b.next(k))
        if (a.target(h) != b.target(k)) return false;
    }
    return true;
  }

  // a = a op b, in place.
  void corefine(Piece& a, Piece& b, Boolean::Op op) {
    // The result is built in the first mesh: its faces that stay are kept
    // where they are, the other's are copied. A union or intersection is
    // symmetric, so the larger mesh takes that place (a box united with a
    // grid of spheres copies the box's faces, not the spheres').
    if (op != Boolean::Op::Difference && b.faces() > a.faces()) std::swap(a, b);
    if (op == Boolean::Op::Union) closeShrunkGaps(a, b);
    if (weldNearVertices(a, b, hairApart(a.box, b.box))) b.shape = 0;
    // Solids stacked face to face on the same triangles need no
    // corefinement (a frustum on the one below it).
    if (op == Boolean::Op::Union && glue(a, b)) {
      ++stats_.glued;
      a.box.include(b.box);
      a.shape = 0;
      keepMoves(a, b, Boolean::Op::Union);
      return;
    }
    ++stats_.corefinements;
    setBooleanInProgress(booleanText(a, b, op));
    stopIfCancelled();
    // In doubles where the operands allow it: several times faster than
    // CGAL's exact corefinement, which takes over where it declines.
    // (The result stays in doubles, for the next boolean and the end.)
    if (order_.doubles) {
      DoubleDecline why = DoubleDecline::NotInDoubles;
      std::optional<DoubleMesh> madeA, madeB;  // an exact operand's doubles
      const DoubleMesh* da = a.doubles                     ? &*a.doubles
                             : (madeA = doublesOf(a.mesh)) ? &*madeA
                                                           : nullptr;
      const DoubleMesh* db = b.doubles                     ? &*b.doubles
                             : (madeB = doublesOf(b.mesh)) ? &*madeB
                                                           : nullptr;
      std::optional<DoubleMesh> made;
      if (da && db) made = doubleBoolean(*da, *db, op, &why);
      bool perturbed = false;
      if (!made && why == DoubleDecline::NotInGeneralPosition && order_.perturb &&
          a.faces() + b.faces() >= kPerturbedFaces) {
        made = perturbedInDoubles(*da, a.box, b, op);
        perturbed = made.has_value();
      }
      if (made) {
        ++stats_.inDoubles;
        stats_.perturbed += perturbed;
        a.doubles = std::move(made);
        a.mesh = Mesh();
        keepMoves(a, b, op, perturbed ? kPerturbedReach * kContactOffset * tolerance_ : 0.0);
        return boxAfter(a);
      }
    }
    if (doublesOnly_) {  // a trial in doubles (the cuts one by one): no CGAL
      declinedInDoubles_ = true;
      return;
    }
    exact(a);
    exact(b);
    // An operand that touches itself (solids that met at a corner, united
    // before: CGAL gave each a vertex of its own there, at one place) must
    // not go into a corefinement whose other operand's surface runs through
    // that corner (CGAL's manual, PMP, corefinement: the inputs must not
    // self-intersect); given one, CGAL crashed, or ran for minutes on a few
    // boxes. The boolean fails instead, and meshOfSolid tries the other
    // order, where the solids meet in another sequence (and, when that
    // fails too, goes ahead: most such meshes CGAL does cut).
    // Going ahead, the boolean is still refused where such an operand
    // truly intersects itself (its coincident points are equal exactly,
    // not only as doubles): CGAL's result is then undefined, and it crashed
    // now and then on the same input (random contact parts, seeds 160, 175).
    // Likewise, until it goes ahead, a small union whose operand crosses
    // itself inside the other: CGAL's corefinement never returned from one
    // (random contact part 2809: two boxes corner to corner, united with a
    // solid grown by a contact over that corner), but makes most such
    // unions, so the refusal only sends the part to other orders first.
    // Not a large one (kSmallCrossing): a stack of 32 thin discs crosses
    // itself so in every order, and CGAL makes it going ahead in 8 s,
    // where each order refused cost 3.5 s more.
    const bool pinchedA = pinchedOn(a.mesh, b), pinchedB = pinchedOn(b.mesh, a);
    if ((pinchedA || pinchedB) &&
        (order_.refusePinches || (pinchedA && PMP::does_self_intersect(a.mesh)) ||
         (pinchedB && PMP::does_self_intersect(b.mesh)))) {
      refusal_ = Refusal::Pinch;
      throw std::runtime_error(booleanText(a, b, op) +
                               " meets a corner where two solids touch, and CGAL cannot cut "
                               "there");
    }
    if (op == Boolean::Op::Union && order_.refusePinches &&
        a.faces() + b.faces() <= kSmallCrossing &&
        (crossesItselfInside(a.mesh, b) || crossesItselfInside(b.mesh, a))) {
      refusal_ = Refusal::Crossing;
      throw std::runtime_error(booleanText(a, b, op) +
                               " has an operand that crosses itself inside the other (solids "
                               "united corner to corner), and CGAL cannot cut there");
    }
    // The operands as they were, for another try.
    const Mesh keptA = a.mesh, keptB = b.mesh;
    const double grownBefore = a.grown, shrunkBefore = a.shrunk;
    keepMoves(a, b, op);
    if (attempt(a, b, op)) {
      if (order_.doubles && a.mesh.number_of_faces() < kPerturbedFaces) roundIfValid(a);
      return boxAfter(a);
    }
    // CGAL cannot make a 2-manifold: the operands touch along an edge (or
    // in a pattern of them), or CGAL stopped half way (two coplanar edges
    // that overlap). The contact is resolved as a perturbation would: a
    // union's operands and a difference's cutter grow by a small part of
    // the tolerance, so that touching operands of a union are joined by a
    // thin bridge and a cut whose pieces touch goes through, leaving the
    // minuend's parts apart; an intersection's second operand shrinks, so
    // that a contact leaves nothing (docs/cli.md, "Contacts"). Where the
    // operands' faces lie in one plane, growing both keeps them there; a
    // union then grows one of them only, which moves its faces off the
    // other's.
    ++stats_.contacts;
    const double delta = kContactOffset * tolerance_;
    struct Offsets {
      double a, b;
    };
    std::vector<Offsets> tries;
    switch (op) {
      case Boolean::Op::Union:
        tries = {{delta, delta}, {0.0, delta}, {delta, 0.0}};
        break;
      case Boolean::Op::Difference:
        tries = {{0.0, delta}};
        break;
      case Boolean::Op::Intersection:
        tries = {{0.0, -delta}};
        break;
    }
    // Both operands grown alike can meet again where they are alike: two
    // octahedra sharing an edge, each grown, have one's corner at an end
    // of the edge on the other's grown face, and the union vertices there
    // that the file's rounding puts in one place, where faces then cross.
    // A try whose result has such vertices near the contact gives way to
    // the next; the first that CGAL made stands if every try does.
    const dvec3 reach(tolerance_);
    const Bounds contact = hairApart(a.box, b.box);
    const Bounds near(contact.lo - reach, contact.hi + reach);
    std::optional<Piece> touching;
    for (const Offsets& offsets : tries) {
      a.mesh = keptA;
      b.mesh = keptB;
      if (offsets.a != 0.0) offsetMesh(a.mesh, offsets.a, {b.box.lo - reach, b.box.hi + reach});
      if (offsets.b != 0.0) offsetMesh(b.mesh, offsets.b, {a.box.lo - reach, a.box.hi + reach});
      a.grown = grownBefore, a.shrunk = shrunkBefore;
      keepMoves(a, b, op, std::max(std::abs(offsets.a), std::abs(offsets.b)));
      if (!attempt(a, b, op)) continue;
      if (!storedTogetherNear(a.mesh, near)) return boxAfter(a);
      if (!touching) touching = a;
    }
    if (!touching) unresolved(a, b, op);
    a = std::move(*touching);
    boxAfter(a);
  }

  // A boolean in doubles that declined for want of general position (the
  // tangent parts of a rounded box: a box's faces in the plane of
  // another's, a cylinder's generators in a box's faces and in another
  // cylinder's cap), made again with b moved off a, as a contact is
  // resolved: grown by a hundredth of the tolerance (docs/cli.md,
  // "Contacts"), also for an intersection: a clip flush with a face of
  // the part (a twisted thread clipped at its foot) then leaves that face
  // where it is, where one shrunk lifted it off the plate it stands on
  // and the part fell into two shells; and shifted by up to a quarter of
  // that on each axis, in a direction taken from the
  // operands' boxes, so that a piece moved so before (now part of a) and
  // b are not moved alike and do not meet in the same place again. It is
  // taken only when b moved the other way gives a result of the same
  // topology (shells and Euler characteristic): the degeneracy was then
  // not a contact, whose resolution is left to CGAL's path (a point
  // contact stays a split, docs/cli.md), and the two differ only by the
  // move. Nothing when either declines or they differ.
  std::optional<DoubleMesh> perturbedInDoubles(const DoubleMesh& a, const Bounds& boxA,
                                               const Piece& b, Boolean::Op op) const {
    const double delta = kContactOffset * tolerance_;
    const double outward = delta;  // b grown, whatever the boolean
    // The boxes' bits, hashed a word at a time in the manner of FNV-1a
    // (its 64-bit offset and prime), seed the standard's fully specified
    // engine: the same shift on every platform, and so the same file.
    std::uint64_t hash = 14695981039346656037u;
    for (const Bounds* box : {&boxA, &b.box})
      for (double x : {box->lo.x, box->lo.y, box->lo.z, box->hi.x, box->hi.y, box->hi.z})
        hash = (hash ^ std::bit_cast<std::uint64_t>(x)) * 1099511628211u;
    std::mt19937 random(std::uint32_t(hash ^ hash >> 32));
    dvec3 shift;
    for (int k = 0; k < 3; ++k) shift[k] = delta * (double(random()) / 0x1p32 - 0.5) / 2.0;
    const Mesh exactB = asExact(b);
    auto moved = [&](double by) {
      Mesh mesh = exactB;
      offsetMesh(mesh, by, Bounds::everything(), shift);
      return doublesOf(mesh).value();  // its points made doubles
    };
    std::optional<DoubleMesh> made = doubleBoolean(a, moved(outward), op);
    if (!made) return std::nullopt;
    const std::optional<DoubleMesh> other = doubleBoolean(a, moved(-outward), op);
    if (!other || topologyOf(*made) != topologyOf(*other)) return std::nullopt;
    return made;
  }

  // A small result of CGAL's corefinement with its points rounded to
  // doubles, where it stays a valid mesh so (meshDefect): the booleans it
  // goes on to may then be made in doubles, which decline a point that is
  // not a double (the union of a rounded box's boxes, whose coplanar
  // faces' diagonals cross at such points, and every boolean after it).
  // The rounding moves a point by half a unit in the last place; the
  // booleans in doubles round each new point so too.
  //
  // Where rounding merges two points that the corefinement put a hair's
  // breadth apart, the faces between them lose their area (the spokes of
  // a wheel, boxes turned about one axis, whose end faces all pass through
  // it: their crossings lie within 1e-16 of each other there). Those faces
  // are collapsed and flipped away as the finished part's are
  // (removeDegenerateFaces), which moves no other point, and the piece is
  // kept in doubles if that leaves it valid; else it stays exact, and
  // every boolean it goes into is CGAL's.
  static void roundIfValid(Piece& piece) {
    Mesh& mesh = piece.mesh;
    const TriangleMesh rounded = trianglesOf(mesh);
    const MeshDefect defect = meshDefect(rounded);
    if (defect.valid()) {
      std::size_t i = 0;
      for (auto v : mesh.vertices()) {
        const dvec3& p = rounded.points[i++];
        mesh.point(v) = typename K::Point_3(p.x, p.y, p.z);
      }
      return;
    }
    if (defect.kind != MeshDefect::Kind::Degenerate) return;
    RoundedMesh repaired;
    for (const dvec3& p : rounded.points) repaired.add_vertex({p.x, p.y, p.z});
    auto tags = tagsOf(repaired);
    const auto exactTags = tagsOf(std::as_const(mesh));
    auto face = mesh.faces().begin();
    using V = RoundedMesh::Vertex_index;
    for (const auto& t : rounded.triangles) {
      const RoundedMesh::Face_index f = repaired.add_face(V(t[0]), V(t[1]), V(t[2]));
      if (f == RoundedMesh::null_face()) return;
      tags[f] = exactTags[*face++];
    }
    removeDegenerateFaces(repaired);
    DoubleMesh doubles{trianglesOf(repaired), {}};
    for (auto f : repaired.faces()) doubles.tags.push_back(tags[f]);
    if (!meshDefect(doubles.mesh).valid()) return;
    piece.doubles = std::move(doubles);
    mesh = Mesh();
  }

  // Solids placed to meet at a corner (a Sierpinski tetrahedron's) meet
  // there only to within the rounding of their coordinates, a few units in
  // the last place: this far, relative to the coordinates' size.
  static double hair(const Bounds& box) {
    const dvec3 lo = glm::abs(box.lo), hi = glm::abs(box.hi);
    return std::max({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) * 0x1p-40;
  }

  // The step between neighbouring coordinates of the file near the box:
  // about the least m·2⁻ᵏ that moves the rounding of m, its largest
  // coordinate (a float's: m·2⁻²⁴ or so), found by bisection on k; 0 when
  // the file keeps every double.
  double storedStep(const Bounds& box) const {
    if (!stored_ || box.empty()) return 0.0;
    const double m = std::ldexp(hair(box), 40);
    int moves = 1, stays = 53;  // m·2⁻¹ moves the rounding; m·2⁻⁵³ does not
    while (stays - moves > 1) {
      const int k = (moves + stays) / 2;
      (stored_(m + std::ldexp(m, -k)) != stored_(m) ? moves : stays) = k;
    }
    return std::ldexp(m, -moves);
  }

  // Solids stacked at a height computed in doubles (a box 0.3 high with
  // another on it at 0.1 + 0.2) stand a unit in the last place off the
  // face they stand on: their boxes are apart, so a union would join them
  // without a boolean, and the file's rounding would then put the two
  // faces in one place, crossing. The same for solids placed less than the
  // file's step apart (a float's, 10⁻⁶ at 10: a tooth at 10 + 10⁻⁷ beside
  // a plate ending at 10), which the file cannot keep apart. Where b's box
  // is apart from a's by no more than that across one axis-aligned plane,
  // and meets it on the other two axes, b's points within that of that
  // side of its box are moved onto a's side, which moves them by twice
  // that at most: the solids then stand on each other exactly, and the
  // union corefines or glues them as it does solids stacked exactly. Both
  // must be in doubles, so that a's side is where its points are.
  // reach: the wider of gapClosed for the two.
  static void closeHairGap(const Piece& a, Piece& b, double reach) {
    if (!a.doubles || !b.doubles || a.box.empty() || b.box.empty() || a.box.overlaps(b.box)) return;
    int axis = -1;
    bool above = false;
    for (int k = 0; k < 3; ++k) {
      const bool over = a.box.hi[k] < b.box.lo[k], under = b.box.hi[k] < a.box.lo[k];
      if (!over && !under) continue;
      const double gap = over ? b.box.lo[k] - a.box.hi[k] : a.box.lo[k] - b.box.hi[k];
      if (axis >= 0 || gap > reach) return;
      axis = k;
      above = over;
    }
    if (axis < 0) return;
    const double from = above ? b.box.lo[axis] : b.box.hi[axis];
    const double to = above ? a.box.hi[axis] : a.box.lo[axis];
    for (dvec3& p : b.doubles->mesh.points)
      if (std::abs(p[axis] - from) <= reach) p[axis] = to;
    b.box = b.doubles->mesh.bounds();
    b.shape = 0;
  }

  // The widest gap between two pieces' sides that closeHairGap closes: a
  // hair, or the file's step, whichever is wider.
  double gapClosed(const Bounds& box) const { return std::max(hair(box), storedStep(box)); }

  // closeHairGap for every pair of the pieces whose boxes come within
  // gapClosed of each other, before any is glued or united (which would
  // take it out of doubles: a stack of plates 0.1 thick at i·0.1, glued
  // where they meet exactly, kept the one gap at 0.6). The pairs are found
  // by a sweep along x over the boxes grown by that, so that a part of
  // thousands of pieces (a Sierpinski tetrahedron's) tests its neighbours
  // only.
  void closeHairGaps(std::vector<Piece>& pieces) const {
    std::vector<std::size_t> order;
    std::vector<double> closed(pieces.size(), 0.0);
    double reach = 0.0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (!pieces[i].doubles || pieces[i].box.empty()) continue;
      order.push_back(i);
      closed[i] = gapClosed(pieces[i].box);
      reach = std::max(reach, closed[i]);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return pieces[a].box.lo.x < pieces[b].box.lo.x;
    });
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = i + 1; j < order.size(); ++j) {
        Piece &a = pieces[order[i]], &b = pieces[order[j]];
        // A snap moves a side by twice the reach at most: boxes sorted by
        // where they began stay within that of their order.
        if (b.box.lo.x > a.box.hi.x + 3.0 * reach) break;
        closeHairGap(a, b, std::max(closed[order[i]], closed[order[j]]));
      }
  }

  // Walls of two pieces a hair apart along an axis made flush (a pin in a
  // swept hole, each placed by its own frame: aligned_walls.h), among the
  // pieces in doubles, before any is glued or united. In a part turned as
  // a whole the frames' entries were snapped to a grid of 2⁻³⁰
  // (EvaluationFrame), which moves a point by a few times that times its
  // distance from the origin, and two walls placed by different frames
  // that far apart are made flush too.
  void alignWalls(std::vector<Piece>& pieces) const {
    std::vector<TriangleMesh*> meshes;
    std::vector<Piece*> owners;
    double reach = 0.0;
    for (Piece& piece : pieces) {
      if (!piece.doubles || piece.box.empty()) continue;
      meshes.push_back(&piece.doubles->mesh);
      owners.push_back(&piece);
      reach = std::max(reach, hair(piece.box));
      const double size = std::ldexp(hair(piece.box), 40);  // its largest coordinate
      if (!frame_.identity) reach = std::max(reach, 0x1p-28 * (1.0 + size));
      // A mesh whose points are all floats, as a file's are (an STL read
      // back): a wall of the part it was exported from lies up to half a
      // float's step from where it was, and a pin made again of that
      // wall's radius that far off it. (Only for a file, which keeps no
      // more than that; a mesh in doubles keeps such walls apart.)
      if (stored_ && frame_.identity && inFloats(piece.doubles->mesh))
        reach = std::max(reach, 0x1p-22 * (1.0 + size));
    }
    const std::vector<bool> moved = alignAxisLines(meshes, reach);
    for (std::size_t i = 0; i < owners.size(); ++i) {
      if (!moved[i]) continue;
      owners[i]->box = meshes[i]->bounds();
      owners[i]->shape = 0;
    }
  }

  // Is every coordinate of the mesh a float?
  static bool inFloats(const TriangleMesh& mesh) {
    return std::all_of(mesh.points.begin(), mesh.points.end(), [](const dvec3& p) {
      return p.x == double(float(p.x)) && p.y == double(float(p.y)) && p.z == double(float(p.z));
    });
  }

  // Where the boxes overlap or come within a hair of each other, grown by
  // a hair; empty when they are further apart.
  static Bounds hairApart(const Bounds& a, const Bounds& b) {
    const dvec3 reach(std::max(hair(a), hair(b)));
    return {glm::max(a.lo, b.lo) - reach, glm::min(a.hi, b.hi) + reach};
  }

  // The boolean of solids that meet at a corner only to a hair would cut
  // a feature a hair wide, which rounding folds (a tetrahedron was lost,
  // and a Sierpinski tetrahedron exported 6 % light). Each vertex of b
  // within a hair of a vertex of a, in the region (hairApart), takes a's
  // point, so that the solids meet exactly and the boolean resolves a
  // plain contact. Returns whether any vertex moved.
  static bool weldNearVertices(Piece& pieceA, Piece& pieceB, const Bounds& region) {
    if (region.empty()) return false;
    const double reach = hair(region);
    struct Corner {
      dvec3 p;
      Vertex v;
      bool ofB;
    };
    std::vector<Corner> corners;
    for (const Piece* piece : {&pieceA, &pieceB}) {
      const bool ofB = piece == &pieceB;
      if (piece->doubles) {
        const std::vector<dvec3>& points = piece->doubles->mesh.points;
        for (std::size_t i = 0; i < points.size(); ++i)
          if (region.contains(points[i])) corners.push_back({points[i], Vertex(i), ofB});
      } else {
        for (Vertex v : piece->mesh.vertices())
          if (const dvec3 p = pointOf(piece->mesh, v); region.contains(p))
            corners.push_back({p, v, ofB});
      }
    }
    std::sort(corners.begin(), corners.end(),
              [](const Corner& l, const Corner& r) { return l.p.x < r.p.x; });
    std::vector<std::pair<Vertex, Vertex>> pairs;  // (of a, of b)
    for (std::size_t i = 0; i < corners.size(); ++i)
      for (std::size_t j = i + 1; j < corners.size() && corners[j].p.x - corners[i].p.x <= reach;
           ++j) {
        const Corner& u = corners[i].ofB ? corners[j] : corners[i];
        const Corner& w = corners[i].ofB ? corners[i] : corners[j];
        const dvec3 d = glm::abs(u.p - w.p);
        if (!u.ofB && w.ofB && u.p != w.p && d.y <= reach && d.z <= reach)
          pairs.emplace_back(u.v, w.v);
      }
    if (pairs.empty()) return false;
    // (exactOf keeps the vertices' numbers.)
    const Mesh& a = exact(pieceA);
    Mesh& b = exact(pieceB);
    // Only where the solids meet at the corner alone: every edge from it
    // leads outside the other solid (its midpoint is outside; its far end
    // may be another contact). Where they overlap around it (the centres
    // of two caps in one plane), the hair does no harm, and two points made
    // one there left CGAL a mesh it refused to cut.
    const CGAL::Side_of_triangle_mesh<Mesh, K> insideA(a), insideB(b);
    auto leadsOut = [](const Mesh& mesh, Vertex v, const auto& otherSide) {
      for (auto h : CGAL::halfedges_around_target(v, mesh))
        if (otherSide(CGAL::midpoint(mesh.point(mesh.source(h)), mesh.point(v))) !=
            CGAL::ON_UNBOUNDED_SIDE)
          return false;
      return true;
    };
    // Every pair is judged before any corner moves: the inside test
    // against b holds a tree over b's faces, and corners of b moved while
    // later pairs were still judged put it out of step with b. (Two
    // Sierpinski tetrahedra of level 5 kept a corner a unit in the last
    // place apart that way, and CGAL's corefinement lost a tetrahedron
    // of the 2 048 there.)
    std::vector<std::pair<Vertex, Vertex>> welds;
    for (const auto& [u, w] : pairs)
      if (leadsOut(a, u, insideB) && leadsOut(b, w, insideA)) welds.emplace_back(u, w);
    for (const auto& [u, w] : welds) b.point(w) = a.point(u);
    return !welds.empty();
  }

  // Has the mesh two vertices in one place inside the other (within its
  // box), and do the faces about them truly cross (the exact test, only
  // then, and only of those faces: of the whole mesh, it cost a stack of
  // 32 discs 8 s to 114 s)?
  static bool crossesItselfInside(const Mesh& mesh, const Piece& other) {
    std::optional<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
    for (const auto& group : coincidentVertices(mesh, other.box)) {
      if (!side) side.emplace(other.mesh);
      if ((*side)(mesh.point(group.front())) != CGAL::ON_BOUNDED_SIDE) continue;
      std::vector<Face> faces;
      for (Vertex v : group)
        for (Face f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
          if (f != Mesh::null_face()) faces.push_back(f);
      if (PMP::does_self_intersect(faces, mesh)) return true;
    }
    return false;
  }

  // Has the mesh two vertices at one place (to doubles), within the other
  // piece's box and on its surface?
  static bool pinchedOn(const Mesh& mesh, const Piece& other) {
    std::optional<CGAL::Side_of_triangle_mesh<Mesh, K>> side;
    for (const auto& group : coincidentVertices(mesh, other.box)) {
      if (!side) side.emplace(other.mesh);
      if ((*side)(mesh.point(group.front())) == CGAL::ON_BOUNDARY) return true;
    }
    return false;
  }

  // Has the mesh two vertices within `near` that the file puts in one
  // place (its rounding, or doubles')?
  bool storedTogetherNear(const Mesh& mesh, const Bounds& near) const {
    std::vector<dvec3> points;
    for (auto v : mesh.vertices())
      if (const dvec3 p = pointOf(mesh, v); near.contains(p))
        points.emplace_back(storedAs(stored_, p.x), storedAs(stored_, p.y), storedAs(stored_, p.z));
    std::sort(points.begin(), points.end(), [](const dvec3& a, const dvec3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
    return std::adjacent_find(points.begin(), points.end()) != points.end();
  }

  // a = a op b by exactBoolean; false when CGAL cannot make a 2-manifold,
  // or throws (a face it cannot cut: the meshes are then half cut, and the
  // caller takes them again as they were).
  static bool attempt(Piece& a, Piece& b, Boolean::Op op) {
    try {
      return exactBoolean(a.mesh, b.mesh, op);
    } catch (const std::exception&) {
      return false;
    }
  }

  static const char* opName(Boolean::Op op) {
    switch (op) {
      case Boolean::Op::Union:
        return "union";
      case Boolean::Op::Intersection:
        return "intersection";
      case Boolean::Op::Difference:
        return "difference";
    }
    return "";
  }

  void boxAfter(Piece& a) {
    a.shape = 0;
    if (a.doubles) {
      a.box = a.doubles->mesh.bounds();
      return;
    }
    CGAL::Bbox_3 box = PMP::bbox(a.mesh);
    a.box = a.empty() ? Bounds{}
                      : Bounds{dvec3(box.xmin(), box.ymin(), box.zmin()),
                               dvec3(box.xmax(), box.ymax(), box.zmax())};
  }

  // "the union of box (part.lua:3) and cylinder (part.lua:5) near (x, y, z)"
  static std::string booleanText(const Piece& a, const Piece& b, Boolean::Op op) {
    const Bounds where = a.box.intersected(b.box);
    char at[200];
    std::snprintf(at, sizeof at, " near (%g, %g, %g)", 0.5 * (where.lo.x + where.hi.x),
                  0.5 * (where.lo.y + where.hi.y), 0.5 * (where.lo.z + where.hi.z));
    return std::string("the ") + opName(op) + " of " + describe(a.origin) + " and " +
           describe(b.origin) + at;
  }

  [[noreturn]] void unresolved(const Piece& a, const Piece& b, Boolean::Op op) {
    throw std::runtime_error(booleanText(a, b, op) +
                             " is not a 2-manifold, even with their contact resolved");
  }

  double tolerance_;
  const EvaluationFrame& frame_;
  std::size_t triangles_ = 0;  // tessellated so far
  MeshBooleanStats& stats_;
  EvaluationOrder order_;
  StoredCoordinate stored_;
  Refusal refusal_ = Refusal::None;
  std::unordered_map<const Material*, std::uint32_t> tags_;
  std::optional<SweptRims> rims_;
};

// The evaluated mesh with its points rounded to doubles (or floats), tags
// kept, in a canonical order. The corefinement returns the same triangles
// in an order that varies from run to run, and the repairs that may follow
// (removeSlivers, removeCrossings) collapse and fill in the mesh's order:
// so the copy takes a canonical order, the points sorted by their
// coordinates and the faces by their corners, and the same part always
// gives the same file.
struct RoundedFaces {
  struct Face {
    std::array<std::uint32_t, 3> corners;  // turned to start at the lowest
    std::uint32_t tag;
    std::uint32_t from;  // its place in the evaluated mesh
  };
  std::vector<dvec3> points;  // sorted
  std::vector<Face> faces;    // sorted by corners
};

// The evaluated mesh as roundedFaces reads it, exact or in doubles: its
// vertex slots, the live ones, each one's point in doubles, the exact
// order of two points, and its faces (corners by slot).
struct ExactSource {
  const ExactMesh& mesh;
  std::size_t slots() const {
    return mesh.number_of_vertices() + mesh.number_of_removed_vertices();
  }
  std::vector<std::uint32_t> vertices() const {
    return {mesh.vertices().begin(), mesh.vertices().end()};
  }
  dvec3 point(std::uint32_t v) const { return pointOf(mesh, ExactMesh::Vertex_index(v)); }
  CGAL::Comparison_result compare(std::uint32_t a, std::uint32_t b) const {
    return CGAL::compare_xyz(mesh.point(ExactMesh::Vertex_index(a)),
                             mesh.point(ExactMesh::Vertex_index(b)));
  }
  std::vector<RoundedFaces::Face> faces() const {
    std::vector<RoundedFaces::Face> out;
    out.reserve(mesh.number_of_faces());
    auto tags = tagsOf(mesh);
    for (auto f : mesh.faces()) {
      RoundedFaces::Face face{{}, tags[f], std::uint32_t(f)};
      int k = 0;
      for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        if (k == 3) throw std::logic_error("meshOfSolid: a face of the result is not a triangle");
        face.corners[k++] = std::uint32_t(v);
      }
      out.push_back(face);
    }
    return out;
  }
};
struct DoubleSource {
  const DoubleMesh& doubles;
  std::size_t slots() const { return doubles.mesh.points.size(); }
  std::vector<std::uint32_t> vertices() const {
    std::vector<std::uint32_t> all(slots());
    for (std::size_t v = 0; v < all.size(); ++v) all[v] = std::uint32_t(v);
    return all;
  }
  dvec3 point(std::uint32_t v) const { return doubles.mesh.points[v]; }
  CGAL::Comparison_result compare(std::uint32_t a, std::uint32_t b) const {
    const dvec3 &p = doubles.mesh.points[a], &q = doubles.mesh.points[b];
    if (p == q) return CGAL::EQUAL;
    return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z) ? CGAL::SMALLER : CGAL::LARGER;
  }
  std::vector<RoundedFaces::Face> faces() const {
    std::vector<RoundedFaces::Face> out(doubles.mesh.size());
    for (std::size_t f = 0; f < out.size(); ++f)
      out[f] = {doubles.mesh.triangles[f], doubles.tags[f], std::uint32_t(f)};
    return out;
  }
};

template <class Source>
RoundedFaces roundedFaces(const Source& source, const EvaluationFrame& frame,
                          StoredCoordinate stored) {
  // Points that rounding to the file's precision put in one place are
  // ordered by their exact places (to_double of a lazy exact number is
  // not a canonical rounding: it depends on what was computed before).
  // (The points are rounded, and both sorts made, on all threads: each
  // order is total, the last tie broken by the index, so it is the same
  // whatever the threads.)
  std::vector<dvec3> points(source.slots());
  std::vector<std::uint32_t> byPlace = source.vertices();
  // Small meshes stay on this thread: starting TBB's scheduler costs
  // about half a millisecond (two frustums glued: 5 % of their export).
  const bool threaded = byPlace.size() >= 10000;
  auto roundPoint = [&](std::size_t i) {
    const std::uint32_t v = byPlace[i];
    dvec3 q = source.point(v);
    if (!frame.identity) q = frame.worldFromEval * q;
    points[v] = dvec3(storedAs(stored, q.x), storedAs(stored, q.y), storedAs(stored, q.z));
  };
  auto placeOrder = [&](std::uint32_t a, std::uint32_t b) {
    const dvec3 &p = points[a], &q = points[b];
    if (p != q) return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
    const CGAL::Comparison_result exactly = source.compare(a, b);
    return exactly != CGAL::EQUAL ? exactly == CGAL::SMALLER : a < b;
  };
  if (threaded) {
    tbb::parallel_for(std::size_t(0), byPlace.size(), roundPoint);
    tbb::parallel_sort(byPlace.begin(), byPlace.end(), placeOrder);
  } else {
    for (std::size_t i = 0; i < byPlace.size(); ++i) roundPoint(i);
    std::sort(byPlace.begin(), byPlace.end(), placeOrder);
  }
  RoundedFaces out;
  // The vertices in that order: vertex[v] is where the mesh's v goes.
  std::vector<std::uint32_t> vertex(points.size());
  out.points.reserve(byPlace.size());
  for (std::size_t i = 0; i < byPlace.size(); ++i) {
    vertex[byPlace[i]] = std::uint32_t(i);
    out.points.push_back(points[byPlace[i]]);
  }
  // A mirror turns the faces inside out on the way back.
  const bool flip = !frame.identity && glm::determinant(frame.worldFromEval) < 0.0;
  out.faces = source.faces();
  for (RoundedFaces::Face& face : out.faces) {
    auto& c = face.corners;
    for (std::uint32_t& corner : c) corner = vertex[corner];
    if (flip) std::swap(c[1], c[2]);
    // Turned to start at its lowest corner: the same face, one way to write it.
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  }
  auto cornerOrder = [](const RoundedFaces::Face& a, const RoundedFaces::Face& b) {
    return a.corners != b.corners ? a.corners < b.corners : a.from < b.from;
  };
  if (threaded)
    tbb::parallel_sort(out.faces.begin(), out.faces.end(), cornerOrder);
  else
    std::sort(out.faces.begin(), out.faces.end(), cornerOrder);
  return out;
}

// Is there nothing for the repairs after rounding to do? No two points in
// one place (separateCoincidentVertices), no face without area
// (removeDegenerateFaces, which finds them by CGAL's exact collinear
// test, as here). Then the rounded mesh is a 2-manifold as the evaluated
// one was: rounding changed no face's corners.
bool needsNoRepair(const RoundedFaces& rounded) {
  for (std::size_t i = 1; i < rounded.points.size(); ++i)
    if (rounded.points[i - 1] == rounded.points[i]) return false;
  auto point = [&](std::uint32_t v) {
    const dvec3& p = rounded.points[v];
    return CGAL::Epick::Point_3(p.x, p.y, p.z);
  };
  return std::none_of(rounded.faces.begin(), rounded.faces.end(), [&](const auto& face) {
    const auto& c = face.corners;
    return CGAL::collinear(point(c[0]), point(c[1]), point(c[2]));
  });
}

// The rounded faces as CGAL's mesh, for the repairs. Adding faces one by
// one can fail in some orders where the finished mesh is fine (a vertex
// whose fans meet only once all are there), so the sorted order, when it
// fails, gives way to the evaluation's, which always succeeded before.
RoundedMesh roundedMeshOf(const RoundedFaces& rounded) {
  auto build = [&](const std::vector<RoundedFaces::Face>& order) -> std::optional<RoundedMesh> {
    RoundedMesh mesh;
    mesh.reserve(rounded.points.size(), order.size() * 3 / 2, order.size());
    for (const dvec3& q : rounded.points) mesh.add_vertex({q.x, q.y, q.z});
    auto tags = tagsOf(mesh);
    using V = RoundedMesh::Vertex_index;
    for (const RoundedFaces::Face& face : order) {
      const auto& t = face.corners;
      RoundedMesh::Face_index g = mesh.add_face(V(t[0]), V(t[1]), V(t[2]));
      if (g == RoundedMesh::null_face()) return std::nullopt;
      tags[g] = face.tag;
    }
    return mesh;
  };
  if (auto mesh = build(rounded.faces)) return std::move(*mesh);
  std::vector<RoundedFaces::Face> made = rounded.faces;
  std::sort(made.begin(), made.end(), [](const auto& a, const auto& b) { return a.from < b.from; });
  if (auto mesh = build(made)) return std::move(*mesh);
  throw std::runtime_error(
      "the result is not a 2-manifold once rounded to the file's precision (faces meet at "
      "a hair's breadth)");
}

// The rounded faces as a PartMesh, as partOf makes it of their CGAL mesh.
PartMesh partOf(const RoundedFaces& rounded, std::vector<MaterialPtr> materials) {
  PartMesh out;
  out.materials = std::move(materials);
  out.mesh.points = rounded.points;
  out.mesh.triangles.reserve(rounded.faces.size());
  out.material.reserve(rounded.faces.size());
  for (const RoundedFaces::Face& face : rounded.faces) {
    out.mesh.triangles.push_back(face.corners);
    out.material.push_back(face.tag);
  }
  return out;
}

// The rounded mesh as a PartMesh.
PartMesh partOf(const RoundedMesh& rounded, std::vector<MaterialPtr> materials) {
  PartMesh out;
  out.materials = std::move(materials);
  out.mesh = trianglesOf(rounded);
  auto tags = tagsOf(rounded);
  out.material.reserve(rounded.number_of_faces());
  for (RoundedMesh::Face_index f : rounded.faces()) out.material.push_back(tags[f]);
  return out;
}

// The mesh of the solid with its unions' operands in the script's order,
// or reversed (meshOfSolid).
PartMesh meshInOrder(const Solid& solid, double tolerance, StoredCoordinate stored,
                     MeshBooleanStats& counts, const EvaluationOrder& order, Refusal& refusal) {
  EvaluationFrame frame(solid);
  frame.written = order.written;
  const Bounds box = frame.evalBounds(solid.bounds());
  // Not for a file that keeps fewer digits than a float near 1 (3MF's six
  // decimals, which lib3mf prints by rules that storedAs follows only
  // nearly): the slivers a perturbation leaves, a fraction of a hundredth
  // of the tolerance wide, were found folded in such a file read back
  // (examples/dxf_flange.lua, 4 of 8 shifts) though not in the check.
  EvaluationOrder evaluationOrder = order;
  evaluationOrder.perturb = storedAs(stored, 1.0 + 0x1p-21) != 1.0;
  Evaluator evaluator(tolerance, frame, counts, evaluationOrder, stored);
  auto piece = [&] {
    try {
      return evaluator.evaluate(solid, box);
    } catch (...) {
      refusal = evaluator.refusal();
      throw;
    }
  }();
  if (piece.empty()) return PartMesh{{}, {}, std::move(evaluator.materials)};

  // A boolean in doubles leaves points on straight creases that hold no
  // shape (collinear_points.h): they go before the mesh is rounded, while
  // their sides are still flat to the last bits.
  stopIfCancelled();  // (each of the finishing steps below takes a while on a large mesh)
  if (piece.doubles)
    dropCollinearPoints(piece.doubles->mesh, piece.doubles->tags, kCollinearReach * tolerance);
  stopIfCancelled();
  const RoundedFaces faces = piece.doubles
                                 ? roundedFaces(DoubleSource{*piece.doubles}, frame, stored)
                                 : roundedFaces(ExactSource{piece.mesh}, frame, stored);
  piece = {};
  stopIfCancelled();
  // The part's mesh from the rounded one, without the slivers a cut left
  // of solids it should have taken whole (removeStrayShells).
  auto partFrom = [&](const auto& mesh) {
    PartMesh made = partOf(mesh, evaluator.materials);
    stopIfCancelled();
    counts.strayShells = removeStrayShells(made, solid, tolerance);
    return made;
  };
  // CGAL's mesh of the rounded faces, made where a repair needs it.
  std::optional<RoundedMesh> rounded;
  auto roundedMesh = [&]() -> RoundedMesh& {
    if (!rounded) rounded = roundedMeshOf(faces);
    return *rounded;
  };
  PartMesh part;
  if (needsNoRepair(faces)) {
    part = partFrom(faces);
  } else {
    // Rounding moves a point that a corefinement put a hair's breadth from
    // another onto it, or onto the line through two others: the faces
    // between them lose their area. CGAL collapses such edges and flips
    // such faces away without moving any other point.
    removeDegenerateFaces(roundedMesh());
    counts.contacts +=
        separateCoincidentVertices(roundedMesh(), kContactOffset * tolerance, stored) > 0;
    part = partFrom(roundedMesh());
  }

  const auto start = std::chrono::steady_clock::now();
  MeshDefect defect = meshDefect(part.mesh);
  // (Only crossings and slivers: parts that touch at a point are reported
  // as they are, not "repaired" into something else.)
  if (defect.kind == MeshDefect::Kind::SelfIntersecting ||
      defect.kind == MeshDefect::Kind::Degenerate) {
    // Rounding can also fold a sliver over its neighbour where faces meet
    // at a hair's breadth (coplanar faces of a rotated union; four faces
    // of turned boxes through one point): the slivers go first, in rounds,
    // since a flip can leave a new sliver beside it (OpenSCAD's rounded
    // box of polygons: 138 crossings, then 18, then none), then what still
    // crosses; each change within kRepairReach of the tolerance, or the
    // crossing stays and the export fails.
    ++counts.repairs;
    const double reach = kRepairReach * tolerance;
    for (int round = 0; round < kSliverRounds && !defect.valid(); ++round) {
      removeSlivers(roundedMesh(), reach);
      part = partFrom(roundedMesh());
      defect = meshDefect(part.mesh);
    }
    // Caps that rounding turned over, which those rounds leave (a grown
    // box's face whose diagonal runs through a corner it touches).
    if (!defect.valid() && flipCaps(roundedMesh(), reach) > 0) {
      part = partFrom(roundedMesh());
      defect = meshDefect(part.mesh);
    }
    // A mesh made with booleans in doubles whose slivers were not all
    // is made again with CGAL's instead (meshTryingDoubles): CGAL's hole
    // filling met NaNs on one (OpenSCAD's example001).
    // CGAL's repair may also drop what it cannot mend: of six wedges
    // united about one edge, two whole wedges went, and the mesh was valid.
    // It is taken only where the volume changes by no more than the reach
    // over the surface; else the crossing stays and the export fails.
    if (!defect.valid() && counts.inDoubles == 0) {
      const double before = part.mesh.volume(), area = part.mesh.area();
      removeCrossings(roundedMesh(), reach);
      PartMesh repaired = partFrom(roundedMesh());
      if (std::abs(repaired.mesh.volume() - before) <= reach * area) {
        part = std::move(repaired);
        defect = meshDefect(part.mesh);
      }
    }
  }
  counts.checkSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!defect.valid()) {
    dvec3 at;
    std::string near;
    if (defectPoint(defect.text, at)) near = primitivesNear(solid, at, kBlameReach * tolerance);
    throw std::runtime_error("the mesh would not be printable: " + defect.text +
                             (near.empty() ? "" : ", made by " + near));
  }
  return part;
}

// The mesh of the solid in that order, with booleans in doubles where the
// order asks for them; if that mesh fails (its check, most likely: the
// booleans in doubles round their new points), the part is made again
// with CGAL's booleans only.
PartMesh meshTryingDoubles(const Solid& solid, double tolerance, StoredCoordinate stored,
                           MeshBooleanStats& counts, const EvaluationOrder& order,
                           Refusal& refusal) {
  if (order.doubles) {
    MeshBooleanStats fast;
    try {
      PartMesh part = meshInOrder(solid, tolerance, stored, fast, order, refusal);
      counts = fast;
      return part;
    } catch (const std::runtime_error&) {
      if (fast.inDoubles == 0) throw;
    }
    refusal = Refusal::None;
    counts.redoneByCgal = true;
  }
  EvaluationOrder exact = order;
  exact.doubles = false;
  return meshInOrder(solid, tolerance, stored, counts, exact, refusal);
}

// Does the tree hold a union of several operands, or a difference with
// several cutters, whose order a second try could change?
bool hasOrderedOperands(const Solid& solid) {
  auto* node = dynamic_cast<const Boolean*>(&solid);
  if (node == nullptr) return false;
  if (node->op() != Boolean::Op::Intersection && node->children().size() > 2) return true;
  if (node->op() == Boolean::Op::Union && node->children().size() > 1) return true;
  return std::any_of(node->children().begin(), node->children().end(),
                     [](const SolidPtr& child) { return hasOrderedOperands(*child); });
}

// meshOfSolid's work, in the orders it tries (below).
PartMesh meshInOrders(const Solid& solid, double tolerance, StoredCoordinate stored,
                      MeshBooleanStats& counts, bool doubles);

// The mesh of a part whose instances are multiplied out: in the orders
// meshInOrders tries, and at last with the sweeps of touching regions
// taken apart (export/sweeps_apart.h); where that fails too, the first
// error.
PartMesh meshOfFlatPart(const Solid& given, double tolerance, StoredCoordinate stored,
                        MeshBooleanStats& counts, bool doubles) {
  const EvaluationFrame frame(given);
  const Bounds box = frame.evalBounds(given.bounds());
  if (!box.empty() && !box.finite())
    throw std::invalid_argument(
        "the part is unbounded, or bounded only by half-spaces, whose reach csgray does not "
        "work out; clip it with a box, clip(s, {lo=, hi=}), to export it");
  // The cylinders it cuts away along a slant (their axes along none of the
  // evaluation's axes), and the turns whose end faces are slanted, made a
  // little longer: their ends, flush with a slanted tube's or bend's, lie
  // in its plane only to rounding (export/lengthened_cutters.h).
  auto slanted = [&](const Primitive& primitive) {
    const glm::dmat4 m = frame.evalFrame(primitive.frame()).worldFromObject();
    auto off = [](const glm::dvec4& v) {
      return int(v.x != 0.0) + int(v.y != 0.0) + int(v.z != 0.0) > 1;
    };
    if (dynamic_cast<const Cylinder*>(&primitive)) return off(m[2]);
    // A turn's end face at its angle lies in a plane of the axes only at a
    // multiple of 90°, and then only if its frame's x and y do.
    if (auto* turn = dynamic_cast<const Revolution*>(&primitive))
      return turn->angleDegrees() < 360.0 &&
             (std::fmod(turn->angleDegrees(), 90.0) != 0.0 || off(m[0]) || off(m[1]));
    return false;
  };
  // Cylinders of one radius cut away across each other, a hair wider
  // (export/widened_cutters.h).
  const SolidPtr lengthened = crossingCuttersWidened(
      cuttersLengthened(given.shared_from_this(), kLengthenedCutters * tolerance, slanted),
      kWidenedCutters * tolerance);
  const Solid& solid = *lengthened;
  try {
    return meshInOrders(solid, tolerance, stored, counts, doubles);
  } catch (const std::runtime_error&) {
    // A part turned as a whole, once more with its solids' places taken
    // back as written (EvaluationFrame), in the script's order. (The
    // lengthened cutters leave its first primitive, and so its frame, as
    // they were.)
    if (frame.moves()) {
      MeshBooleanStats attempt;
      Refusal refusal = Refusal::None;
      EvaluationOrder asWritten;
      asWritten.doubles = doubles;
      asWritten.written = true;
      try {
        PartMesh mesh = meshTryingDoubles(solid, tolerance, stored, attempt, asWritten, refusal);
        attempt.framesAsWritten = true;
        counts = attempt;
        return mesh;
      } catch (const std::runtime_error&) {
      }
    }
    // The last tries, each from the part as given, rewritten; whatever
    // stops them, the first error stands: holes that pins of their radius
    // fill left out (export/filled_holes.h); cylinders cut away made a
    // little longer (export/lengthened_cutters.h); sweeps of touching regions
    // taken apart (export/sweeps_apart.h); sweeps side by side merged even
    // where that touches itself, and sweeps of regions that touch
    // themselves opened there (export/opened_pinches.h).
    const SolidPtr part = solid.shared_from_this();
    const std::pair<std::function<SolidPtr()>, bool MeshBooleanStats::*> lastTries[] = {
        {[&] { return filledHolesDropped(part); }, &MeshBooleanStats::holesFilled},
        {[&] {
           return cuttersLengthened(part, kLengthenedCutters * tolerance,
                                    [](const Primitive&) { return true; });
         },
         &MeshBooleanStats::cuttersLengthened},
        {[&] { return sweepsTakenApart(part); }, &MeshBooleanStats::sweepsApart},
        {[&] { return pinchesOpened(sweepsMerged(part, true), kContactOffset * tolerance); },
         &MeshBooleanStats::pinchesOpened},
    };
    for (const auto& [rewritten, made] : lastTries) {
      try {
        const SolidPtr changed = rewritten();
        if (changed.get() == &solid) continue;
        PartMesh mesh = meshInOrders(*changed, tolerance, stored, counts, doubles);
        counts.*made = true;
        return mesh;
      } catch (const std::exception&) {
      }
    }
    throw;
  }
}

}  // namespace

const char* booleanInProgress() { return inProgress; }

PartMesh meshOfSolid(const Solid& solid, double tolerance, StoredCoordinate stored,
                     MeshBooleanStats* stats, bool doubles) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("the tolerance must be a positive number");
  // The mesh of each primitive is made in the world: instances multiplied out.
  if (solid.hasInstances())
    return meshOfSolid(*flattened(solid.shared_from_this()), tolerance, stored, stats, doubles);
  // Booleans of prisms of one height (export/prism_booleans.h) and sweeps
  // side by side (export/merged_sweeps.h) are made as one, in the plane;
  // should that fail, the part is made as it has them.
  MeshBooleanStats local;
  MeshBooleanStats& counts = stats ? *stats : local;
  if (const SolidPtr merged =
          sweepsMerged(prismBooleansMerged(solid.shared_from_this(), kPinchBridge * tolerance));
      merged.get() != &solid) {
    try {
      return meshOfFlatPart(*merged, tolerance, stored, counts, doubles);
    } catch (const std::exception&) {  // (a merged sweep's mesh refused: the part's own error)
    }
  }
  return meshOfFlatPart(solid, tolerance, stored, counts, doubles);
}

namespace {

PartMesh meshInOrders(const Solid& solid, double tolerance, StoredCoordinate stored,
                      MeshBooleanStats& counts, bool doubles) {
  // Where several solids touch near one place, the offsets that resolve
  // their contacts (docs/cli.md, "Contacts") are made pair by pair in the
  // order the booleans meet them, and an order can leave two moved faces
  // crossing, or a mesh that touches itself where a later operand cuts.
  // The other order meets the same contacts the other way round: of 300
  // random parts of touching boxes, balls and cylinders, 8 failed or
  // crashed in the script's order, and 5 of them export so. A boolean
  // refused for such a corner in both orders is then made as it comes;
  // one refused for an operand of a union that crosses itself inside the
  // other is first tried in a few shuffled orders, still refusing (CGAL
  // never finished one such union). The error reported is the first one
  // that is not such a refusal. When every order fails, a
  // few shuffled orders, going ahead, meet the contacts in yet other
  // sequences (7 of 600 such random parts export only so; a part that
  // cannot be made takes that much longer to say so).
  constexpr unsigned kShuffledOrders = 4;
  const bool ordered = hasOrderedOperands(solid);
  // As written and reversed, each refusing, then going ahead.
  std::vector<EvaluationOrder> orders = {{false, true, doubles}};
  if (ordered) orders.push_back({true, true, doubles});
  if (ordered)
    for (unsigned seed = 1; seed <= kShuffledOrders; ++seed)
      orders.push_back({false, true, doubles, seed});
  orders.push_back({false, false, doubles});
  if (ordered) orders.push_back({true, false, doubles});
  if (ordered)
    for (unsigned seed = 1; seed <= kShuffledOrders; ++seed)
      orders.push_back({false, false, doubles, seed});
  std::exception_ptr first, firstNotRefused;
  bool anyRefused = false, anyCrossing = false;
  for (const EvaluationOrder& order : orders) {
    // Shuffled orders that refuse follow a crossing refused, and the
    // orders going ahead any refusal: otherwise they would do what was
    // done. After pinches alone the part goes ahead at once: a large one
    // that CGAL makes so (a stack of 32 thin discs, 8 s) would pay four
    // orders more.
    if (order.refusePinches && order.shuffle != 0 && !anyCrossing) continue;
    if (!order.refusePinches && order.shuffle == 0 && !anyRefused) continue;
    MeshBooleanStats attempt;
    Refusal refusal = Refusal::None;
    try {
      PartMesh part = meshTryingDoubles(solid, tolerance, stored, attempt, order, refusal);
      attempt.reordered = order.reversed ? 1 : order.shuffle == 0 ? 0 : 1 + order.shuffle;
      counts = attempt;
      return part;
    } catch (const std::runtime_error&) {
      if (!first) first = std::current_exception();
      if (refusal == Refusal::None && !firstNotRefused) firstNotRefused = std::current_exception();
      anyRefused = anyRefused || refusal != Refusal::None;
      anyCrossing = anyCrossing || refusal == Refusal::Crossing;
    }
  }
  std::rethrow_exception(firstNotRefused ? firstNotRefused : first);
}

}  // namespace

}  // namespace csgray::detail
