#include "scene/modifiers.h"

#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "engine/boolean.h"
#include "engine/instance.h"

namespace csgray::detail {

const char* modifierName(Modifier modifier) {
  switch (modifier) {
    case Modifier::Highlight:
      return "highlight";
    case Modifier::Ghost:
      return "ghost";
    case Modifier::Only:
      return "only";
    case Modifier::Disable:
      return "disable";
  }
  return "modifier";
}

MarkedSolid::MarkedSolid(Modifier modifier, SolidPtr marked)
    : modifier_(modifier), marked_(std::move(marked)) {
  primitives_ = marked_->primitiveCount();
  booleans_ = marked_->booleanCount();
  // A level of its own: every walk over the tree recurses through it, and
  // a mark put on a mark 20 000 times overflowed the stack.
  depth_ = marked_->depth() + 1;
  if (depth_ > Boolean::kMaxDepth)
    throw std::invalid_argument(std::string(modifierName(modifier_)) + ": tree deeper than " +
                                std::to_string(Boolean::kMaxDepth) + " levels");
  insideBeyondWindow_ = marked_->insideBeyondWindow();
  instances_ = marked_->hasInstances();
  setOrigin(marked_->origin());
}

const Bounds& MarkedSolid::bounds() const { return inModel() ? marked_->bounds() : empty_; }

void MarkedSolid::spans(const Ray& ray, SpanList& out) const {
  if (inModel()) return marked_->spans(ray, out);
  out.clear();
}

void MarkedSolid::spansToFirstBoundary(const Ray& ray, SpanList& out) const {
  if (inModel()) return marked_->spansToFirstBoundary(ray, out);
  out.clear();
}

bool MarkedSolid::contains(const dvec3& p) const { return inModel() && marked_->contains(p); }

std::string MarkedSolid::kind() const {
  return std::string(modifierName(modifier_)) + " " + marked_->kind();
}

SolidPtr MarkedSolid::mapPrimitives(const PrimitiveMap& f) const {
  auto mapped = std::make_shared<MarkedSolid>(modifier_, marked_->mapPrimitives(f));
  mapped->setOrigin(origin());
  return mapped;
}

namespace {

// Walks a tree, rebuilding it without marks and collecting what they mark.
class Resolver {
 public:
  // The solid without marks, or null when nothing of it is in the model.
  SolidPtr resolve(const SolidPtr& solid) {
    if (auto* marked = dynamic_cast<const MarkedSolid*>(solid.get())) return resolveMarked(*marked);
    // Marks under an instance are taken out of a copy in the world's frame,
    // so that the ghosts and highlights are where the instance puts them.
    if (auto* instance = dynamic_cast<const Instance*>(solid.get()))
      return unmarked(instance->child()) ? solid : resolve(flattened(solid));
    auto* boolean = dynamic_cast<const Boolean*>(solid.get());
    if (!boolean) return solid;  // a primitive
    std::vector<SolidPtr> operands;
    for (const SolidPtr& operand : boolean->children())
      if (SolidPtr resolved = resolve(operand)) operands.push_back(std::move(resolved));
    if (operands.empty()) return nullptr;
    return boolean->withOperands(std::move(operands));
  }

  ResolvedModifiers result(const std::vector<SolidPtr>& model) && {
    if (onlies_.empty()) return {model, std::move(ghosts_), std::move(highlights_)};
    ResolvedModifiers only;
    for (ResolvedModifiers& o : onlies_) {
      only.model.insert(only.model.end(), o.model.begin(), o.model.end());
      only.ghosts.insert(only.ghosts.end(), o.ghosts.begin(), o.ghosts.end());
      only.highlights.insert(only.highlights.end(), o.highlights.begin(), o.highlights.end());
    }
    return only;
  }

 private:
  SolidPtr resolveMarked(const MarkedSolid& marked) {
    switch (marked.modifier()) {
      case Modifier::Disable:
        return nullptr;
      case Modifier::Ghost:
        // A ghost is shown as the solid it marks would be alone: its own
        // marks inside are resolved, but they are not the model's.
        if (SolidPtr shown = modelOf(marked.marked())) ghosts_.push_back(std::move(shown));
        return nullptr;
      case Modifier::Highlight: {
        SolidPtr resolved = resolve(marked.marked());
        if (resolved) highlights_.push_back(resolved);
        return resolved;
      }
      case Modifier::Only: {
        // A fresh walk, so that the ghosts and highlights of the only()
        // solid go with it and those elsewhere are dropped with the rest.
        Resolver inner;
        SolidPtr resolved = inner.resolve(marked.marked());
        std::vector<SolidPtr> model;
        if (resolved) model.push_back(resolved);
        onlies_.push_back(std::move(inner).result(model));
        return resolved;
      }
    }
    return nullptr;
  }

  // Is the tree free of marks? Each shared node is looked at once.
  bool unmarked(const SolidPtr& solid) {
    if (auto known = unmarked_.find(solid.get()); known != unmarked_.end()) return known->second;
    bool free = !dynamic_cast<const MarkedSolid*>(solid.get());
    for (const SolidPtr& child : solid->children()) free = free && unmarked(child);
    unmarked_.emplace(solid.get(), free);
    return free;
  }

  std::vector<SolidPtr> ghosts_, highlights_;
  std::vector<ResolvedModifiers> onlies_;
  std::unordered_map<const Solid*, bool> unmarked_;
};

}  // namespace

ResolvedModifiers resolveModifiers(const std::vector<SolidPtr>& solids) {
  Resolver resolver;
  std::vector<SolidPtr> model;
  for (const SolidPtr& solid : solids)
    if (SolidPtr resolved = resolver.resolve(solid)) model.push_back(std::move(resolved));
  return std::move(resolver).result(model);
}

SolidPtr modelOf(const SolidPtr& solid) {
  std::vector<SolidPtr> model = resolveModifiers({solid}).model;
  if (model.empty()) return nullptr;
  return model.size() == 1 ? model.front() : unionOf(std::move(model));
}

}  // namespace csgray::detail
