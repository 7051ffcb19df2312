#include "mesh/mesh_boolean.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <unordered_map>

#include "mesh/mesh_validity.h"
#include "modeler/boolean.h"
#include "modeler/primitive.h"

namespace csgray {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
// The result, rounded to what a file holds.
using RoundedMesh = CGAL::Surface_mesh<Inexact::Point_3>;

constexpr const char* kTag = "f:material";
// The booleans hold each triangle in exact arithmetic, some hundreds of
// bytes: this many are a few GB.
constexpr std::size_t kMaxExportTriangles = 10'000'000;

template <class Mesh>
auto tagsOf(Mesh& mesh) {
  return mesh.template add_property_map<typename Mesh::Face_index, std::uint32_t>(kTag, 0).first;
}
template <class Mesh>
auto tagsOf(const Mesh& mesh) {
  return const_cast<Mesh&>(mesh)
      .template property_map<typename Mesh::Face_index, std::uint32_t>(kTag)
      .first;
}

// A corefinement cuts faces into triangles and copies faces from one mesh
// into the other; each new face keeps the material tag it came from.
template <class Mesh>
struct TagVisitor : PMP::Corefinement::Default_visitor<Mesh> {
  using Face = typename Mesh::Face_index;
  std::uint32_t splitTag = 0;
  void before_subface_creations(Face split, Mesh& mesh) { splitTag = tagsOf(mesh)[split]; }
  void after_subface_created(Face created, Mesh& mesh) { tagsOf(mesh)[created] = splitTag; }
  void after_face_copy(Face from, const Mesh& source, Face to, Mesh& target) {
    tagsOf(target)[to] = tagsOf(source)[from];
  }
};

// The frame the booleans are evaluated in. A part turned as a whole (or
// mirrored) has that turn folded into every primitive's frame, where it is
// rounded: a hole's top and the plate's top face, flush before the turn,
// no longer lie on one plane, and the corefinement leaves slivers that do
// not survive rounding to the file's precision. So the tree is evaluated
// in the frame of its first primitive's rotation: each primitive's frame
// is taken back through that rotation, and its entries, off by rounding
// only, are snapped to a grid of 2⁻³⁰ (a change of about 10⁻⁹, far below
// any tolerance), which makes flush faces flush again. The result is
// turned back at the end.
struct EvaluationFrame {
  glm::dmat3 worldFromEval{1.0};
  glm::dmat3 evalFromWorld{1.0};
  bool identity = true;

  explicit EvaluationFrame(const Solid& solid) {
    const Solid* first = &solid;
    while (!first->children().empty()) first = first->children()[0].get();
    auto* primitive = dynamic_cast<const Primitive*>(first);
    if (!primitive) return;
    const glm::dmat3 linear(primitive->frame().worldFromObject());
    // Only a rotation or a mirror (orthonormal columns), so that the
    // tolerance means the same in both frames.
    const glm::dmat3 gram = glm::transpose(linear) * linear;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        if (std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)) > 1e-12) return;
    if (linear == glm::dmat3(1.0)) return;
    worldFromEval = linear;
    evalFromWorld = glm::transpose(linear);
    identity = false;
  }

  static double snapped(double x) { return std::ldexp(std::nearbyint(std::ldexp(x, 30)), -30); }

  Affine evalFrame(const Affine& frame) const {
    glm::dmat4 m = glm::dmat4(evalFromWorld) * frame.worldFromObject();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) m[c][r] = snapped(m[c][r]);
    return Affine::fromMatrix(m);
  }
  Bounds evalBounds(const Bounds& b) const {
    if (identity || !b.finite()) return b;
    Bounds out;
    for (int i = 0; i < 8; ++i)
      out.include(evalFromWorld *
                  dvec3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z));
    return out;
  }
};

// Evaluates the tree with exact constructions (Epeck): a corefinement's new
// points are exact, so the next boolean in a chain sees them where they
// are (CGAL's manual, PMP, "Corefinement and Boolean Operations": with
// inexact constructions a chained result may self-intersect, and CGAL's
// face triangulation may then crash). Measured on plate(8), Epick was no
// faster: CGAL computes the intersection points exactly either way.
class Evaluator {
 public:
  using K = Exact;
  using Mesh = CGAL::Surface_mesh<typename K::Point_3>;
  using Face = typename Mesh::Face_index;
  using Vertex = typename Mesh::Vertex_index;

  // Part of the tree, evaluated: a mesh and the box of its points.
  struct Piece {
    Mesh mesh;
    Bounds box;
    bool empty() const { return mesh.number_of_faces() == 0; }
  };

  Evaluator(double tolerance, const EvaluationFrame& frame, MeshBooleanStats& stats)
      : tolerance_(tolerance), frame_(frame), stats_(stats) {}

  // A mesh M with M ∩ region = solid ∩ region; M may reach past the region
  // (an unbounded primitive is meshed within a larger box), which the
  // operations above it cut away.
  Piece evaluate(const Solid& solid, const Bounds& outer) {
    const Bounds region = outer.intersected(frame_.evalBounds(solid.bounds()));
    if (region.empty()) return {};
    if (auto* primitive = dynamic_cast<const Primitive*>(&solid)) return leaf(*primitive, region);
    auto* node = dynamic_cast<const Boolean*>(&solid);
    if (!node) throw std::logic_error("meshOfSolid: unknown solid " + solid.kind());
    std::span<const SolidPtr> operands = node->children();
    switch (node->op()) {
      case Boolean::Op::Union: {
        std::vector<Piece> pieces;
        for (const SolidPtr& s : operands) pieces.push_back(evaluate(*s, region));
        return unite(std::move(pieces));
      }
      case Boolean::Op::Intersection: {
        std::vector<Piece> pieces;
        for (const SolidPtr& s : operands) {
          pieces.push_back(evaluate(*s, region));
          if (pieces.back().empty()) return {};
        }
        return balanced(std::move(pieces), Boolean::Op::Intersection);
      }
      case Boolean::Op::Difference: {
        Piece minuend = evaluate(*operands[0], region);
        if (minuend.empty()) return minuend;
        // Whatever is cut away is cut from the minuend's mesh, which may
        // reach past the region: the cutters are meshed over all of it.
        std::vector<Piece> cutters;
        for (const SolidPtr& s : operands.subspan(1)) cutters.push_back(evaluate(*s, minuend.box));
        Piece cut = unite(std::move(cutters));
        if (cut.empty() || !minuend.box.overlaps(cut.box)) return minuend;
        corefine(minuend, cut, Boolean::Op::Difference);
        return minuend;
      }
    }
    return {};
  }

  std::vector<MaterialPtr> materials;

 private:
  std::uint32_t tagOf(const MaterialPtr& material) {
    auto [it, added] = tags_.try_emplace(material.get(), std::uint32_t(materials.size()));
    if (added) materials.push_back(material);
    return it->second;
  }

  Piece leaf(const Primitive& primitive, const Bounds& region) {
    ++stats_.primitives;
    TriangleMesh triangles = frame_.identity
                                 ? primitive.tessellate(tolerance_, region)
                                 : std::dynamic_pointer_cast<const Primitive>(
                                       primitive.withFrame(frame_.evalFrame(primitive.frame())))
                                       ->tessellate(tolerance_, region);
    // Each primitive keeps within its limit; the whole part within
    // kMaxExportTriangles, checked as each is added (before its exact
    // copy, several times the size, is made).
    triangles_ += triangles.size();
    if (triangles_ > kMaxExportTriangles) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "the part needs more than %zu triangles at a tolerance of %g; give a larger "
                    "tolerance",
                    kMaxExportTriangles, tolerance_);
      throw std::invalid_argument(text);
    }
    Piece piece;
    if (triangles.empty()) return piece;
    Mesh& mesh = piece.mesh;
    mesh.reserve(triangles.points.size(), triangles.size() * 3 / 2, triangles.size());
    for (const dvec3& p : triangles.points) mesh.add_vertex(typename K::Point_3(p.x, p.y, p.z));
    auto tags = tagsOf(mesh);
    const std::uint32_t tag = tagOf(primitive.material());
    for (const TriangleMesh::Triangle& t : triangles.triangles) {
      Face f = mesh.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2]));
      if (f == Mesh::null_face())
        throw std::logic_error(primitive.kind() + ": its tessellation is not a 2-manifold");
      tags[f] = tag;
    }
    piece.box = triangles.bounds();
    return piece;
  }

  // Adds b's shells to a: their boxes are apart, so no face of one meets
  // the other.
  void join(Piece& a, Piece& b) {
    tagsOf(b.mesh);
    a.mesh.join(b.mesh);
    a.box.include(b.box);
    ++stats_.merges;
  }

  // Pieces whose boxes are pairwise apart are joined into one group; the
  // groups are then united pairwise in a balanced order, so that no mesh
  // is corefined more than log₂(groups) times. (Boxes are closed,
  // Bounds::overlaps: operands that touch are corefined, not joined.)
  Piece unite(std::vector<Piece> pieces) {
    std::vector<Piece> groups;
    std::vector<std::vector<Bounds>> members;
    for (Piece& piece : pieces) {
      if (piece.empty()) continue;
      std::size_t g = 0;
      while (g < groups.size() &&
             std::any_of(members[g].begin(), members[g].end(),
                         [&](const Bounds& b) { return b.overlaps(piece.box); }))
        ++g;
      if (g == groups.size()) {
        groups.push_back(std::move(piece));
        members.push_back({groups.back().box});
      } else {
        members[g].push_back(piece.box);
        join(groups[g], piece);
      }
    }
    return balanced(std::move(groups), Boolean::Op::Union);
  }

  Piece balanced(std::vector<Piece> pieces, Boolean::Op op) {
    if (pieces.empty()) return {};
    while (pieces.size() > 1) {
      std::vector<Piece> next;
      for (std::size_t i = 0; i + 1 < pieces.size(); i += 2) {
        Piece& a = pieces[i];
        Piece& b = pieces[i + 1];
        if (!a.box.overlaps(b.box)) {
          if (op == Boolean::Op::Intersection) return {};
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

  // a = a op b, in place.
  void corefine(Piece& a, Piece& b, Boolean::Op op) {
    ++stats_.corefinements;
    // The result is built in the first mesh: its faces that stay are kept
    // where they are, the other's are copied. A union or intersection is
    // symmetric, so the larger mesh takes that place (a box united with a
    // grid of spheres copies the box's faces, not the spheres').
    if (op != Boolean::Op::Difference && b.mesh.number_of_faces() > a.mesh.number_of_faces())
      std::swap(a, b);
    tagsOf(a.mesh);
    tagsOf(b.mesh);
    TagVisitor<Mesh> visitor;
    auto np = CGAL::parameters::visitor(visitor);
    bool ok = false;
    const char* name = "";
    switch (op) {
      case Boolean::Op::Union:
        ok = PMP::corefine_and_compute_union(a.mesh, b.mesh, a.mesh, np);
        name = "union";
        break;
      case Boolean::Op::Intersection:
        ok = PMP::corefine_and_compute_intersection(a.mesh, b.mesh, a.mesh, np);
        name = "intersection";
        break;
      case Boolean::Op::Difference:
        ok = PMP::corefine_and_compute_difference(a.mesh, b.mesh, a.mesh, np);
        name = "difference";
        break;
    }
    if (!ok) {
      Bounds where = a.box.intersected(b.box);
      char at[160];
      std::snprintf(at, sizeof at, "(%g, %g, %g)..(%g, %g, %g)", where.lo.x, where.lo.y, where.lo.z,
                    where.hi.x, where.hi.y, where.hi.z);
      throw std::runtime_error(std::string("the ") + name + " of two operands within " + at +
                               " is not a 2-manifold: they touch along an edge or at a point; "
                               "move one a little, or let them overlap");
    }
    CGAL::Bbox_3 box = PMP::bbox(a.mesh);
    a.box = a.empty() ? Bounds{}
                      : Bounds{dvec3(box.xmin(), box.ymin(), box.zmin()),
                               dvec3(box.xmax(), box.ymax(), box.zmax())};
  }

  double tolerance_;
  const EvaluationFrame& frame_;
  std::size_t triangles_ = 0;  // tessellated so far
  MeshBooleanStats& stats_;
  std::unordered_map<const Material*, std::uint32_t> tags_;
};

// The evaluated mesh with its points rounded to doubles (or floats), tags
// kept.
template <class Mesh>
RoundedMesh roundedCopy(const Mesh& exact, const EvaluationFrame& frame, StoredCoordinate stored) {
  RoundedMesh rounded;
  rounded.reserve(exact.number_of_vertices(), exact.number_of_edges(), exact.number_of_faces());
  std::vector<RoundedMesh::Vertex_index> vertex(exact.number_of_vertices() +
                                                exact.number_of_removed_vertices());
  auto round = [stored](double d) { return stored ? stored(d) : d; };
  for (auto v : exact.vertices()) {
    const auto& p = exact.point(v);
    dvec3 q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if (!frame.identity) q = frame.worldFromEval * q;
    vertex[v] = rounded.add_vertex({round(q.x), round(q.y), round(q.z)});
  }
  // A mirror turns the faces inside out on the way back.
  const bool flip = !frame.identity && glm::determinant(frame.worldFromEval) < 0.0;
  auto tags = tagsOf(rounded);
  auto exactTags = tagsOf(exact);
  for (auto f : exact.faces()) {
    std::array<RoundedMesh::Vertex_index, 3> t;
    int k = 0;
    for (auto v : CGAL::vertices_around_face(exact.halfedge(f), exact)) {
      if (k == 3) throw std::logic_error("meshOfSolid: a face of the result is not a triangle");
      t[k++] = vertex[v];
    }
    if (flip) std::swap(t[1], t[2]);
    RoundedMesh::Face_index g = rounded.add_face(t[0], t[1], t[2]);
    if (g == RoundedMesh::null_face())
      throw std::runtime_error(
          "the result is not a 2-manifold once rounded to the file's precision (faces meet at "
          "a hair's breadth)");
    tags[g] = exactTags[f];
  }
  return rounded;
}

// The rounded mesh as a PartMesh.
PartMesh partOf(const RoundedMesh& rounded, std::vector<MaterialPtr> materials) {
  PartMesh out;
  out.materials = std::move(materials);
  std::vector<std::uint32_t> index(rounded.number_of_vertices() +
                                   rounded.number_of_removed_vertices());
  out.mesh.points.reserve(rounded.number_of_vertices());
  for (RoundedMesh::Vertex_index v : rounded.vertices()) {
    index[v] = std::uint32_t(out.mesh.points.size());
    const auto& p = rounded.point(v);
    out.mesh.points.emplace_back(p.x(), p.y(), p.z());
  }
  auto tags = tagsOf(rounded);
  out.mesh.triangles.reserve(rounded.number_of_faces());
  out.material.reserve(rounded.number_of_faces());
  for (RoundedMesh::Face_index f : rounded.faces()) {
    TriangleMesh::Triangle t{};
    int k = 0;
    for (RoundedMesh::Vertex_index v : CGAL::vertices_around_face(rounded.halfedge(f), rounded))
      t[k++ % 3] = index[v];
    out.mesh.triangles.push_back(t);
    out.material.push_back(tags[f]);
  }
  return out;
}

}  // namespace

PartMesh meshOfSolid(const Solid& solid, double tolerance, StoredCoordinate stored,
                     MeshBooleanStats* stats) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("the tolerance must be a positive number");
  const EvaluationFrame frame(solid);
  const Bounds box = frame.evalBounds(solid.bounds());
  if (!box.empty() && !box.finite())
    throw std::invalid_argument(
        "the part is unbounded, or bounded only by half-spaces, whose reach csgray does not "
        "work out; clip it with a box, clip(s, {lo=, hi=}), to export it");
  MeshBooleanStats local;
  MeshBooleanStats& counts = stats ? *stats : local;
  Evaluator evaluator(tolerance, frame, counts);
  auto piece = evaluator.evaluate(solid, box);
  if (piece.empty()) return PartMesh{{}, {}, std::move(evaluator.materials)};

  RoundedMesh rounded = roundedCopy(piece.mesh, frame, stored);
  // Rounding moves a point that a corefinement put a hair's breadth from
  // another onto it, or onto the line through two others: the faces between
  // them lose their area. CGAL collapses such edges and flips such faces
  // away without moving any other point.
  PMP::remove_degenerate_faces(rounded);
  PartMesh part = partOf(rounded, evaluator.materials);

  const auto start = std::chrono::steady_clock::now();
  std::string defect = meshDefect(part.mesh);
  // (Only crossings and slivers: parts that touch at a point are reported
  // as they are, not "repaired" into something else.)
  if (defect.starts_with("self-intersecting") || defect.starts_with("degenerate")) {
    // Rounding can also fold a sliver over its neighbour where faces meet
    // at a hair's breadth (coplanar faces of a rotated union): CGAL removes
    // the faces that cross and fills the holes they leave. Its smoothing
    // and hole filling may move the surface far (a vertex of a rotated
    // union moved 1.2 mm: csgray check found it), so every patch must stay
    // within a hundredth of the tolerance of the faces it replaces, or the
    // crossing stays and the export fails.
    ++counts.repairs;
    PMP::experimental::remove_self_intersections(
        rounded, CGAL::parameters::polyhedral_envelope_epsilon(0.01 * tolerance));
    PMP::remove_degenerate_faces(rounded);
    part = partOf(rounded, evaluator.materials);
    defect = meshDefect(part.mesh);
  }
  counts.checkSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!defect.empty()) throw std::runtime_error("the mesh would not be printable: " + defect);
  return part;
}

}  // namespace csgray
