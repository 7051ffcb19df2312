#include "check/model_pieces.h"

#include <algorithm>
#include <bit>
#include <glm/geometric.hpp>
#include <numeric>
#include <vector>

#include "engine/boolean.h"
#include "engine/instance.h"
#include "engine/solvers/quadric_form.h"
#include "primitives/profile_sweep.h"
#include "primitives/quadric.h"
#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

// Groups joined by union-find.
struct Groups {
  std::vector<std::size_t> parent;
  explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t root(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a), b = root(b);
    if (a != b) parent[b] = a;
  }
};

// The pieces a sweep is: its region's outer loops once evaluated (the
// letters of a word, cells apart), each counterclockwise.
std::size_t sweptPieces(const Solid& solid) {
  auto* sweep = dynamic_cast<const RegionSweep*>(&solid);
  if (sweep == nullptr) return 1;
  const Region& region = *sweep->sweptRegion();
  std::size_t outer = 0;
  Profile loop;
  for (const ProfileLoop& each : evaluate(region, evaluationTolerance(region)).loops) {
    loop.loops = {each};
    outer += area(loop) > 0.0;
  }
  return std::max<std::size_t>(outer, 1);
}

// Which sheet of a two-sheet quadric (a hyperboloid of two sheets, a
// hyperbolic cylinder, the outside of two parallel planes) the world point
// p lies on, −1 or +1; 0 where `solid` is no such quadric, nor an
// intersection or a difference whose solid lies within one. In the
// quadric's canonical form Σ λᵢyᵢ² + c ≤ 0 with c > 0 and a single λᵢ < 0,
// no point of the solid has yᵢ = 0, so the sheets are the two sides of
// that plane. A clip of one to a box is then as many pieces as sides it
// has points on: each sheet's inside is convex, and so is the box.
int sheetOf(const Solid& solid, const dvec3& p) {
  if (auto* quadric = dynamic_cast<const Quadric*>(&solid)) {
    const QuadricForm form = canonicalQuadricForm(quadric->matrix());
    if (form.linear != 0.0 || !(form.constant > 0.0)) return 0;
    int negative = -1;
    for (int i = 0; i < 3; ++i) {
      if (form.lambda[i] >= 0.0) continue;
      if (negative >= 0) return 0;
      negative = i;
    }
    if (negative < 0) return 0;
    const double y = form.toCanonical(quadric->frame().pointToObject(p))[negative];
    return y < 0.0 ? -1 : 1;
  }
  if (auto* instance = dynamic_cast<const Instance*>(&solid))
    return sheetOf(*instance->child(), instance->frame().pointToObject(p));
  auto* node = dynamic_cast<const Boolean*>(&solid);
  if (node == nullptr || node->op() == Boolean::Op::Union) return 0;
  for (const SolidPtr& child : node->children()) {
    if (const int side = sheetOf(*child, p)) return side;
    if (node->op() == Boolean::Op::Difference) break;  // only the minuend bounds it
  }
  return 0;
}

// The operands of the part's top union, unions within it looked through;
// the part itself where it is no union.
std::vector<const Solid*> unionOperands(const Solid& solid) {
  std::vector<const Solid*> operands;
  std::vector<const Solid*> pending = {&solid};
  while (!pending.empty()) {
    const Solid* s = pending.back();
    pending.pop_back();
    auto* node = dynamic_cast<const Boolean*>(s);
    if (node && node->op() == Boolean::Op::Union) {
      for (const SolidPtr& child : node->children()) pending.push_back(child.get());
    } else if (!s->bounds().empty()) {
      operands.push_back(s);
    }
  }
  return operands;
}

// Joins each shell to the operands its faces lie on: those that hold a
// point `depth` inside a face's middle (where the mesh lies within the
// tolerance of the surface, inside the solid the face stands for), and
// marks them found, with the sheets of a two-sheet quadric they lie on
// (sheetOf: bit 1 the negative side, bit 2 the positive). Sweeps along
// x, the operands' boxes against the points; false where the tests ran
// past a budget.
bool joinShellsToOperands(const TriangleMesh& mesh, const MeshShells& shells,
                          const std::vector<const Solid*>& operands, double depth,
                          std::size_t shellIds, Groups& groups, std::vector<bool>& found,
                          std::vector<unsigned>& sheets) {
  std::vector<std::pair<dvec3, std::size_t>> points;  // and their shells
  points.reserve(mesh.triangles.size());
  for (const TriangleMesh::Triangle& t : mesh.triangles) {
    const dvec3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const dvec3 normal = glm::cross(b - a, c - a);
    const double length = glm::length(normal);
    if (length > 0.0)
      points.emplace_back((a + b + c) / 3.0 - (depth / length) * normal, shells.shellOfPoint[t[0]]);
  }
  std::sort(points.begin(), points.end(),
            [](const auto& p, const auto& q) { return p.first.x < q.first.x; });
  std::vector<std::size_t> order(operands.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return operands[i]->bounds().lo.x < operands[j]->bounds().lo.x;
  });
  std::vector<std::size_t> active;  // operands begun along x, not yet left behind
  std::size_t next = 0, budget = 20'000'000;
  for (const auto& [p, shell] : points) {
    while (next < order.size() && operands[order[next]]->bounds().lo.x <= p.x)
      active.push_back(order[next++]);
    std::erase_if(active, [&](std::size_t k) { return operands[k]->bounds().hi.x < p.x; });
    for (std::size_t k : active) {
      if (budget-- == 0) return false;
      const std::size_t node = shellIds + k;
      if (groups.root(node) == groups.root(shell) || !operands[k]->bounds().contains(p) ||
          !operands[k]->contains(p))
        continue;
      groups.join(shell, node);
      found[k] = true;
      if (const int side = sheetOf(*operands[k], p)) sheets[k] |= side < 0 ? 1u : 2u;
    }
  }
  return true;
}

}  // namespace

std::size_t modelPieces(const Solid& solid, const TriangleMesh& mesh, const MeshShells& shells,
                        double near) {
  const std::vector<const Solid*> operands = unionOperands(solid);
  if (operands.empty()) return 1;
  // Nodes: the shells' numbers, then the operands.
  std::size_t shellIds = 0;
  for (std::uint32_t s : shells.shellOfPoint) shellIds = std::max<std::size_t>(shellIds, s + 1);
  Groups groups(shellIds + operands.size());
  std::vector<bool> found(operands.size(), false);
  std::vector<unsigned> sheets(operands.size(), 0);
  const std::optional<std::vector<std::uint32_t>> touching = shellGroupsWithin(mesh, shells, near);
  if (touching)
    for (std::size_t s = 0; s < shellIds; ++s) groups.join(s, (*touching)[s]);
  if (!touching ||
      !joinShellsToOperands(mesh, shells, operands, near, shellIds, groups, found, sheets)) {
    std::fill(found.begin(), found.end(), false);
    std::fill(sheets.begin(), sheets.end(), 0u);
  }
  // Where no shell was found on an operand (or the shells were too many
  // to weigh), what its box overlaps: at most as many pieces as there are.
  for (std::size_t i = 0; i < operands.size(); ++i)
    for (std::size_t j = i + 1; j < operands.size(); ++j)
      if ((!found[i] || !found[j]) && operands[i]->bounds().overlaps(operands[j]->bounds()))
        groups.join(shellIds + i, shellIds + j);
  std::vector<std::size_t> members(groups.parent.size(), 0);
  for (std::size_t k = 0; k < operands.size(); ++k) ++members[groups.root(shellIds + k)];
  std::size_t pieces = 0;
  for (std::size_t k = 0; k < operands.size(); ++k) {
    const std::size_t r = groups.root(shellIds + k);
    if (members[r] == 0) continue;  // counted
    pieces += members[r] > 1
                  ? 1
                  : std::max<std::size_t>(sweptPieces(*operands[k]), std::popcount(sheets[k]));
    members[r] = 0;
  }
  return std::max<std::size_t>(pieces, 1);
}

}  // namespace csgray::detail
