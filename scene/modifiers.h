// OpenSCAD's modifier characters on solids (docs/script.md, Modifiers):
// `#` highlight, `%` ghost, `!` only, `*` disable. A marked solid is a node
// of the tree that holds the solid it marks, so that the mark goes along
// with transforms, materials and booleans; when the script's result becomes
// a scene, resolveModifiers takes the marks out: the model loses its ghosts
// and disabled solids (and, under an only(), everything else), and the
// scene keeps the ghosts and the highlighted solids in lists of their own,
// which a renderer draws and a viewer may switch off.
#pragma once

#include <string>
#include <vector>

#include "engine/solid.h"

namespace csgray::detail {

enum class Modifier { Highlight, Ghost, Only, Disable };

// The method that sets it: "highlight", "ghost", "only", "disable".
const char* modifierName(Modifier modifier);

class MarkedSolid : public Solid {
 public:
  MarkedSolid(Modifier modifier, SolidPtr marked);

  Modifier modifier() const { return modifier_; }
  const SolidPtr& marked() const { return marked_; }
  // Is the marked solid part of the model? A ghost and a disabled solid
  // are not: as a tree node they are empty (a ghost cut from a part cuts
  // nothing), which is what a query in the script (bounds, contains) sees.
  bool inModel() const { return modifier_ == Modifier::Highlight || modifier_ == Modifier::Only; }

  const Bounds& bounds() const override;
  void spans(const Ray& ray, SpanList& out) const override;
  void spansToFirstBoundary(const Ray& ray, SpanList& out) const override;
  bool firstBoundaryCutsShort() const override { return marked_->firstBoundaryCutsShort(); }
  bool contains(const dvec3& p) const override;
  void prepare() const override { marked_->prepare(); }
  std::span<const SolidPtr> children() const override { return {&marked_, 1}; }
  std::string kind() const override;
  SolidPtr mapPrimitives(const PrimitiveMap& f) const override;

 private:
  Modifier modifier_;
  SolidPtr marked_;
  Bounds empty_;
};

// A tree without its marks, and what they marked.
struct ResolvedModifiers {
  std::vector<SolidPtr> model;       // what is rendered, exported and checked
  std::vector<SolidPtr> ghosts;      // shown see-through, not part of the model
  std::vector<SolidPtr> highlights;  // parts of the model, drawn over the image
};

// Takes the marks out of the solids: ghosts and disabled solids leave the
// booleans they are in (an intersection or a difference goes on with its
// other operands, as in OpenSCAD, whose tree drops them); when any solid
// is marked only(), the model is the only() solids alone, with the ghosts
// and highlights within them. A tree that is left with nothing adds nothing.
ResolvedModifiers resolveModifiers(const std::vector<SolidPtr>& solids);
// One solid's model, or null when nothing is left of it: what check() in
// a script and the exporter see.
SolidPtr modelOf(const SolidPtr& solid);

}  // namespace csgray::detail
