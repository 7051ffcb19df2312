#include "engine/flat_union.h"

#include <optional>
#include <vector>

#include "engine/boolean.h"
#include "engine/instance.h"

namespace csgray::detail {

namespace {

bool isUnion(const Solid& solid) {
  const Boolean* node = solid.asBoolean();
  return node && node->op() == Boolean::Op::Union;
}

// A union, or a chain of uses that ends in one?
bool unionUnderUses(const Solid& solid) {
  if (const Instance* use = solid.asInstance()) return unionUnderUses(*use->child());
  return isUnion(solid);
}

// Appends the leaves of the nesting below solid, each moved by outer (when
// given) after the uses' frames on the way to it.
void collectLeaves(const SolidPtr& solid, const std::optional<Affine>& outer,
                   std::vector<SolidPtr>& leaves) {
  if (isUnion(*solid)) {
    for (const SolidPtr& operand : solid->children()) collectLeaves(operand, outer, leaves);
    return;
  }
  if (const Instance* use = solid->asInstance(); use && unionUnderUses(*use->child())) {
    collectLeaves(use->child(), outer ? use->frame().then(*outer) : use->frame(), leaves);
    return;
  }
  // A primitive is copied with the composed frame; any other node (or a
  // use of one) becomes a use in the composed frame.
  leaves.push_back(outer ? solid->transformed(*outer) : solid);
}

}  // namespace

bool nestsMovedUnions(const Solid& solid) {
  if (const Instance* use = solid.asInstance()) return unionUnderUses(*use->child());
  if (!isUnion(solid)) return false;
  for (const SolidPtr& operand : solid.children())
    if (operand->asInstance() ? unionUnderUses(*operand) : nestsMovedUnions(*operand)) return true;
  return false;
}

SolidPtr flatUnion(const SolidPtr& solid, std::size_t maxLeaves) {
  if (solid->primitiveCount() > maxLeaves || !nestsMovedUnions(*solid)) return solid;
  std::vector<SolidPtr> leaves;
  leaves.reserve(solid->primitiveCount());
  collectLeaves(solid, std::nullopt, leaves);
  if (leaves.size() == 1) return leaves[0];
  auto flat = std::make_shared<Boolean>(Boolean::Op::Union, std::move(leaves));
  flat->setOrigin(solid->origin());
  flat->prepare();
  return flat;
}

SolidPtr keptFlatUnion(const Solid& node, std::once_flag& made, SolidPtr& kept) {
  std::call_once(made, [&] {
    SolidPtr flat = flatUnion(node.shared_from_this());
    if (flat.get() != &node) kept = std::move(flat);
  });
  return kept ? kept : node.shared_from_this();
}

}  // namespace csgray::detail
