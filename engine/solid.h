// A solid: a closed point set, possibly unbounded, that answers three
// questions. It is an immutable value: transforms and materials return new
// solids, so a script may reuse one part in many places.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/affine.h"
#include "engine/bounds.h"
#include "engine/span_list.h"

namespace csgray::detail {

// What a primitive is made of (scene/material.h): the engine only carries
// it from the script to the renderer and the exporter.
struct Material;
using MaterialPtr = std::shared_ptr<const Material>;

class Solid;
class Primitive;
class Boolean;
class Instance;
using SolidPtr = std::shared_ptr<const Solid>;

// Where a script made a solid: its file and line, for messages that point
// the user at the shape in question ("box at part.lua:12").
struct SourceLine {
  std::shared_ptr<const std::string> file;  // shared: thousands of solids come from one script
  int line = 0;
  // The line of the script's main chunk that led there, when the solid was
  // made inside a function: two calls of one function make solids on the
  // same line, and this tells them apart.
  int via = 0;

  bool known() const { return file && line > 0; }
  // "part.lua:12", "part.lua:12 via line 30", or "" when unknown.
  std::string text() const;
};

class Solid : public std::enable_shared_from_this<Solid> {
 public:
  virtual ~Solid() = default;

  // World-space box that holds the whole solid (conservative).
  virtual const Bounds& bounds() const = 0;
  // A box that holds the solid moved by outer (after its own frames), for
  // an instance's box (engine/instance.h). By default the box of bounds()'s
  // corners moved; primitives and small boolean nodes make it from their
  // parts, which under a rotation is tighter: a ball's box stays a ball's,
  // where the moved corners of its cube reach up to √3 times as far.
  virtual Bounds boundsUnder(const Affine& outer) const;
  // The box a BVH over operands holds this solid by: bounds() by default,
  // an instance's from boundsUnder. Apart from bounds(), which frames a
  // scene without a camera, so that such a scene is framed as before.
  virtual const Bounds& rayBox() const { return bounds(); }
  // Spans of the ray inside the solid, written to out (cleared first).
  // They are exact within [ray.tMin, ray.tMax]; outside it a span may be
  // left out, or end at a boundary other than the solid's (a union whose
  // operand lies wholly before the window starts its span later), so only
  // boundaries within the window are answers.
  virtual void spans(const Ray& ray, SpanList& out) const = 0;
  // Like spans(), for a ray that needs only the solid's first boundary
  // within the window (a camera ray, a shadow ray): where that boundary is
  // and whether the ray enters or leaves there are exact, and an empty list
  // means the solid does not meet the window; the spans beyond that first
  // boundary may not be the solid's.
  virtual void spansToFirstBoundary(const Ray& ray, SpanList& out) const { spans(ray, out); }
  // May spansToFirstBoundary's spans beyond the first boundary differ from
  // spans()'s (a shape that stops looking there)? A difference asks its
  // first operand for the first boundary alone only then, since where a
  // hole covers that boundary it needs the rest and must ask again.
  virtual bool firstBoundaryCutsShort() const { return false; }
  // Does the solid meet the open window (tMin, tMax), some stretch of it
  // inside there? What an opaque solid's shadow ray asks: the answer of
  // spansToFirstBoundary's spans, but any hit stops the search, not only
  // the nearest (a union stops at the first operand that meets it).
  // scratch is working space.
  virtual bool meetsWindow(const Ray& ray, SpanList& scratch) const;
  // Beyond the window, do the spans that spans() writes lie inside the
  // solid? True of primitives, whose spans are whole, and of unions and
  // intersections of such solids, which an operand left out only makes
  // smaller; a difference asked about a window leaves out the holes beyond it.
  bool insideBeyondWindow() const { return insideBeyondWindow_; }
  // Is p in the closed point set (up to rounding on the surface)?
  virtual bool contains(const dvec3& p) const = 0;

  // Builds what spans() would otherwise build on first use (a boolean
  // node's BVH), so that a renderer can do it before its threads start.
  virtual void prepare() const {}
  // The same point set as rays walk it fastest: unions nested under
  // transforms as one union of their leaves (engine/flat_union.h), made on
  // first use and kept by the node; the solid itself otherwise.
  virtual SolidPtr forRays() const { return shared_from_this(); }

  // Operands of a boolean node, the shared child of an instance (in the
  // instance's frame, engine/instance.h); none for a primitive.
  virtual std::span<const SolidPtr> children() const { return {}; }
  // A short description: "sphere", "union", ...
  virtual std::string kind() const = 0;
  // This node as a boolean node or an instance, else null: for walks over
  // the tree on a ray's path (the search for the use of a shaded boundary,
  // engine/instance_surface.h), where a dynamic_cast cost about a hundred
  // instructions per node (6 % of the lens field's render).
  virtual const Boolean* asBoolean() const { return nullptr; }
  virtual const Instance* asInstance() const { return nullptr; }

  // The same tree with every primitive p replaced by f(p).
  // Instances are multiplied out: f sees each use of a shared primitive,
  // in the world's frame.
  using PrimitiveMap = std::function<SolidPtr(const Primitive&)>;
  virtual SolidPtr mapPrimitives(const PrimitiveMap& f) const = 0;
  // The same, for maps that do not depend on where a primitive is (a
  // material): f sees each distinct primitive once, in its own frame, and
  // the result shares what this tree shares. done holds the nodes mapped
  // so far.
  using SharedMap = std::unordered_map<const Solid*, SolidPtr>;
  virtual SolidPtr mapSharedPrimitives(const PrimitiveMap& f, SharedMap& /*done*/) const {
    return mapPrimitives(f);
  }
  // Is there an instance (engine/instance.h) in the tree?
  bool hasInstances() const { return instances_; }

  // Size of the tree: primitives and boolean nodes below and including this
  // one, counting a shared subtree once per use (as rays visit it), and the
  // number of boolean levels.
  std::size_t primitiveCount() const { return primitives_; }
  std::size_t booleanCount() const { return booleans_; }
  int depth() const { return depth_; }

  // Where the script made this solid. Copies made by transforms and
  // materials keep it. The script API sets it once, on a solid it has just
  // built and not yet shared, which is why a const solid may take it.
  const SourceLine& origin() const { return origin_; }
  void setOrigin(SourceLine origin) const { origin_ = std::move(origin); }

  // This solid moved by worldFromObject (applied after any transform it
  // has): a primitive is copied with the composed frame, a boolean node or
  // an instance becomes an instance that shares the tree.
  SolidPtr transformed(const Affine& worldFromObject) const;
  // This solid with the material given to every primitive that has none
  // (the instances' children mapped once, so a subtree shared elsewhere
  // keeps its own materials there).
  SolidPtr withDefaultMaterial(const MaterialPtr& material) const;

 protected:
  std::size_t primitives_ = 1;
  std::size_t booleans_ = 0;
  int depth_ = 0;
  bool insideBeyondWindow_ = true;
  bool instances_ = false;
  mutable SourceLine origin_;
};

// Counts of a tree, for `csgray info`: primitives and booleans as the part
// uses them (a subtree placed by several instances counts once per use),
// and the primitives stored, each shared subtree counted once.
struct TreeStats {
  std::size_t primitives = 0;
  std::size_t booleans = 0;
  std::size_t storedPrimitives = 0;
};
TreeStats treeStats(const Solid& solid);

}  // namespace csgray::detail
