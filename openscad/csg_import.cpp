#include "openscad/csg_import.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "engine/boolean.h"
#include "engine/degrees.h"
#include "engine/printable_token.h"
#include "engine/tight_bounds.h"
#include "io/height_map_file.h"
#include "io/input_file.h"
#include "openscad/openscad_sweeps.h"
#include "primitives/linear_extrusion.h"
#include "primitives/mesh_solid.h"
#include "primitives/revolution.h"
#include "profile/dxf_reader.h"
#include "profile/glyph_outlines.h"
#include "profile/region_evaluation.h"
#include "profile/shapes.h"
#include "profile/svg_reader.h"
#include "scene/color_names.h"
#include "scene/hull_shapes.h"
#include "scene/material.h"
#include "scene/modifiers.h"
#include "scene/resize.h"
#include "scene/rotation.h"
#include "scene/shapes.h"
#include "scene/value_checks.h"

namespace csgray::detail {

int openscadFragments(double r, double fn, double fa, double fs) {
  // OpenSCAD's GRID_FINE: below it a circle is a point, made a triangle.
  if (r < 0.00000095367431640625) return 3;
  const double n =
      fn > 0.0 ? std::max(fn, 3.0)
               : std::ceil(std::max(std::min(360.0 / fa, 2.0 * std::numbers::pi * r / fs), 5.0));
  if (!(n <= kMaxOpenScadFragments))
    throw std::invalid_argument(
        "$fn, $fa and $fs ask for " + std::to_string(std::llround(std::min(n, 1e18))) +
        " sides of a circle, more than " + std::to_string(kMaxOpenScadFragments));
  return int(n);
}

namespace {

constexpr std::size_t kMaxFileBytes = std::size_t{256} << 20;

// What a node makes: a solid, a region, or nothing (an empty group).
struct Shape {
  SolidPtr solid;
  RegionPtr region;
  bool empty() const { return !solid && !region; }
};

// A fault of the node: the importer adds the file and the node's line.
struct NodeError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class Importer {
 public:
  Importer(const std::string& fileName, const CsgImportOptions& options)
      : file_(fileName),
        source_(std::make_shared<const std::string>(fileName)),
        options_(options) {}

  CsgModel model(const std::vector<CsgNode>& nodes) {
    CsgModel model;
    for (const CsgNode& node : nodes) {
      Shape s = shape(node);
      if (s.solid) model.solids.push_back(s.solid);
      if (s.region) model.regions.push_back(s.region);
    }
    return model;
  }

 private:
  Shape shape(const CsgNode& node) {
    try {
      Shape s = marked(node, made(node));
      if (s.solid) placeOrigin(*s.solid, node.line);
      warnOfUnread(node);
      return s;
    } catch (const CsgError&) {
      throw;
    } catch (const std::exception& e) {
      // The node's name once: the script API's messages start with it too.
      const std::string what = e.what(), name = node.name + ": ";
      throw CsgError(file_ + ":" + std::to_string(node.line) + ": " +
                     (what.starts_with(name) ? what : name + what));
    }
  }

  // The node's line for the solid, and for the nodes below it made for it
  // (those that have none yet): export's messages and csgray view's pick
  // name it, as they name a script's lines.
  void placeOrigin(const Solid& solid, int line) const {
    if (solid.origin().known()) return;
    solid.setOrigin(SourceLine{source_, line});
    for (const SolidPtr& child : solid.children()) placeOrigin(*child, line);
  }

  // OpenSCAD's modifier characters; a region's % and * leave it out.
  Shape marked(const CsgNode& node, Shape s) {
    if (!node.modifier || s.empty()) return s;
    const Modifier m = node.modifier == '#'   ? Modifier::Highlight
                       : node.modifier == '%' ? Modifier::Ghost
                       : node.modifier == '!' ? Modifier::Only
                                              : Modifier::Disable;
    if (s.solid) return {std::make_shared<MarkedSolid>(m, s.solid), nullptr};
    if (m == Modifier::Ghost || m == Modifier::Disable) return {};
    return s;
  }

  // A parameter the node's making never read: OpenSCAD's special variables
  // ($fn, ...) are the nodes' to take or leave, and some parameters that
  // OpenSCAD writes mean nothing to an exact model (a preview's convexity,
  // a file's time stamp, an extrusion's slices, the DXF layer and origin
  // OpenSCAD writes for any import); a node made before (a repeated
  // offset, whose first copy was read) is not read again.
  void warnOfUnread(const CsgNode& node) {
    const auto read = read_.find(&node);
    if (read == read_.end()) return;
    auto meaningless = [&](const std::string& key) {
      return key.starts_with("$") || key == "convexity" || key == "timestamp" ||
             (node.name == "linear_extrude" && (key == "slices" || key == "segments")) ||
             (node.name == "import" && (key == "layer" || key == "origin"));
    };
    for (const auto& [key, value] : node.named) {
      if (meaningless(key) || read->second.contains(key)) continue;
      // The nearest name the node asked for, if it is a slip of a letter
      // or two (centre for center).
      std::string nearest;
      std::size_t best = key.size() >= 5 ? 3 : 2;
      for (const std::string& asked : read->second)
        if (const std::size_t d = editDistance(key, asked); d < best) best = d, nearest = asked;
      options_.warn(file_ + ":" + std::to_string(node.line) + ": " + node.name + ": parameter '" +
                    printableToken(key, 40) + "' is not known here and was left out" +
                    (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
    }
    read_.erase(read);
  }

  // ---- Arguments -----------------------------------------------------------

  const CsgValue* find(const CsgNode& node, const char* key, int position = -1) const {
    if (options_.warn) read_[&node].insert(key);  // (only a listener needs them)
    if (auto it = node.named.find(key); it != node.named.end()) return &it->second;
    if (position >= 0 && position < int(node.positional.size())) return &node.positional[position];
    return nullptr;
  }

  static bool given(const CsgValue* v) { return v && v->kind != CsgValue::Kind::Undef; }

  double number(const CsgNode& node, const char* key, double fallback, int position = -1) const {
    const CsgValue* v = find(node, key, position);
    if (!given(v)) return fallback;
    if (v->kind != CsgValue::Kind::Number) throw NodeError(std::string(key) + " must be a number");
    return definedNumber(v->number, key);
  }

  // OpenSCAD writes nan for arithmetic without a value (0/0, sqrt(-1)): no
  // parameter takes it, and a shape that left it out would hide the slip.
  static double definedNumber(double x, const std::string& what) {
    if (std::isnan(x)) throw NodeError(what + " is nan (an undefined number in the source)");
    return x;
  }

  std::string string(const CsgNode& node, const char* key, const std::string& fallback,
                     int position = -1) const {
    const CsgValue* v = find(node, key, position);
    if (!given(v)) return fallback;
    if (v->kind != CsgValue::Kind::String) throw NodeError(std::string(key) + " must be a string");
    return v->text;
  }

  bool boolean(const CsgNode& node, const char* key, bool fallback) const {
    const CsgValue* v = find(node, key);
    if (!given(v)) return fallback;
    if (v->kind == CsgValue::Kind::Number) return v->number != 0.0;
    if (v->kind != CsgValue::Kind::Boolean)
      throw NodeError(std::string(key) + " must be a boolean");
    return v->boolean;
  }

  static std::vector<double> numbers(const CsgValue& v, const std::string& what) {
    if (v.kind != CsgValue::Kind::Vector) throw NodeError(what + " must be a vector of numbers");
    std::vector<double> out;
    for (const CsgValue& item : v.items) {
      if (item.kind != CsgValue::Kind::Number) throw NodeError(what + " must hold numbers only");
      out.push_back(definedNumber(item.number, what));
    }
    return out;
  }

  // Lists of point indices (a polyhedron's faces, a polygon's paths).
  static std::vector<std::vector<std::int64_t>> indexLists(const CsgValue& lists,
                                                           const std::string& what) {
    std::vector<std::vector<std::int64_t>> out;
    for (const CsgValue& list : lists.items) {
      std::vector<std::int64_t> indices;
      for (double i : numbers(list, what)) {
        if (!(i >= 0.0 && i == std::floor(i) && i < 9e15))
          throw NodeError(what + "'s indices must be whole numbers from 0");
        indices.push_back(std::int64_t(i));
      }
      out.push_back(std::move(indices));
    }
    return out;
  }

  // A number n or a vector [x, y(, z)] as a vector of size `size`.
  dvec3 numberOrVector(const CsgNode& node, const char* key, int size, dvec3 fallback,
                       int position = -1) const {
    const CsgValue* v = find(node, key, position);
    if (!given(v)) return fallback;
    if (v->kind == CsgValue::Kind::Number) return dvec3(definedNumber(v->number, key));
    std::vector<double> n = numbers(*v, key);
    if (int(n.size()) < size)
      throw NodeError(std::string(key) + " must have " + std::to_string(size) + " numbers");
    dvec3 out(fallback);
    for (int i = 0; i < size; ++i) out[i] = n[i];
    return out;
  }

  // OpenSCAD's $fn, $fa and $fs of the node.
  OpenScadResolution resolution(const CsgNode& node) const {
    OpenScadResolution r{number(node, "$fn", 0.0), number(node, "$fa", 12.0),
                         number(node, "$fs", 2.0)};
    if (!(r.fa > 0.0) || !(r.fs > 0.0)) throw NodeError("$fa and $fs must be > 0");
    return r;
  }

  // Does the node ask for a polygon of n sides rather than a circle?
  int polygonSides(const CsgNode& node, double r) const {
    const OpenScadResolution res = resolution(node);
    if (options_.facets == CsgFacets::OpenScad) return openscadFragments(r, res.fn, res.fa, res.fs);
    if (res.fn >= 1.0 && res.fn <= kShapeFacets) return std::max(int(res.fn), 3);
    return 0;  // exact
  }

  // ---- Children ------------------------------------------------------------

  // Which empty children make a boolean empty, as in OpenSCAD: none of a
  // union's, the first of a difference's, any of an intersection's
  // (cube(0), or the empty group() an if that fails leaves).
  enum class EmptyChild { Skipped, EmptiesIfFirst, Empties };

  // The shapes of the children; those that make nothing are left out,
  // or make the whole empty (nothing returned) as `empty` says.
  std::vector<Shape> children(const CsgNode& node, EmptyChild empty = EmptyChild::Skipped) {
    std::vector<Shape> shapes;
    for (const CsgNode& child : node.children) {
      Shape s = shape(child);
      // A child that a modifier leaves out (a region's % or *) is no
      // operand at all, as in OpenSCAD.
      const bool leftOut = child.modifier == '%' || child.modifier == '*';
      if (s.empty() && !leftOut &&
          (empty == EmptyChild::Empties ||
           (empty == EmptyChild::EmptiesIfFirst && &child == &node.children.front())))
        return {};
      if (!s.empty()) shapes.push_back(std::move(s));
    }
    return shapes;
  }

  // OpenSCAD's booleans: union of all, intersection of all, the first minus
  // the others; of solids or of regions, not of both.
  Shape booleanOf(const CsgNode& node, Boolean::Op op) {
    std::vector<Shape> shapes =
        children(node, op == Boolean::Op::Difference     ? EmptyChild::EmptiesIfFirst
                       : op == Boolean::Op::Intersection ? EmptyChild::Empties
                                                         : EmptyChild::Skipped);
    if (shapes.empty()) return {};
    const bool solids = bool(shapes.front().solid);
    for (const Shape& s : shapes)
      if (bool(s.solid) != solids)
        throw NodeError("mixes 2D and 3D children; extrude the 2D ones first");
    if (shapes.size() == 1) return shapes.front();
    if (solids) {
      std::vector<SolidPtr> operands;
      for (const Shape& s : shapes) operands.push_back(s.solid);
      return {booleanShape(op, std::move(operands)), nullptr};
    }
    std::vector<RegionPtr> operands;
    for (const Shape& s : shapes) operands.push_back(s.region);
    const Region::Op regionOp = op == Boolean::Op::Union          ? Region::Op::Union
                                : op == Boolean::Op::Intersection ? Region::Op::Intersection
                                                                  : Region::Op::Difference;
    return {nullptr, Region::boolean(regionOp, std::move(operands))};
  }

  // The children's union as one region, for the sweeps and offsets.
  RegionPtr regionOfChildren(const CsgNode& node) {
    Shape s = booleanOf(node, Boolean::Op::Union);
    if (s.solid) throw NodeError("takes 2D children, not solids");
    return s.region;
  }

  // ---- Nodes ---------------------------------------------------------------

  Shape made(const CsgNode& node) {
    const std::string& n = node.name;
    if (n == "group" || n == "union" || n == "render" || n == "colorless")
      return booleanOf(node, Boolean::Op::Union);
    if (n == "difference") return booleanOf(node, Boolean::Op::Difference);
    if (n == "intersection") return booleanOf(node, Boolean::Op::Intersection);
    if (n == "multmatrix") return multmatrix(node);
    if (n == "color") return color(node);
    if (n == "cube") return cube(node);
    if (n == "sphere") return sphere(node);
    if (n == "cylinder") return cylinder(node);
    if (n == "polyhedron") return polyhedron(node);
    if (n == "square") return square(node);
    if (n == "circle") return circle(node);
    if (n == "polygon") return polygon(node);
    if (n == "linear_extrude") return linearExtrude(node);
    if (n == "rotate_extrude") return rotateExtrude(node);
    if (n == "offset") return remembered(node, &Importer::offset);
    if (n == "resize") return resize(node);
    if (n == "hull") return hullOf(node);
    if (n == "import") return importFile(node);
    if (n == "minkowski") return minkowskiOf(node);
    if (n == "text") return text(node);
    if (n == "projection") return remembered(node, &Importer::projection);
    if (n == "surface") return surface(node);
    throw NodeError("unknown node");
  }

  // The costly 2D nodes (offsets, projections) are made once for each
  // subtree written alike: OpenSCAD's files repeat them (GEB offsets each of
  // its letters three times), and a region is an immutable value to share.
  Shape remembered(const CsgNode& node, Shape (Importer::*make)(const CsgNode&)) {
    std::string key = csgNodeKey(node);
    if (auto it = made2D_.find(key); it != made2D_.end()) return it->second;
    Shape s = (this->*make)(node);
    made2D_.emplace(std::move(key), s);
    return s;
  }

  // OpenSCAD's text(), sized and laid out as OpenSCAD does
  // (TextLayout::Metrics::OpenScad): the font's curves, or with OpenSCAD's
  // facets the chords OpenSCAD draws them with.
  Shape text(const CsgNode& node) {
    TextLayout layout;
    layout.metrics = TextLayout::Metrics::OpenScad;
    layout.blankMakesNothing = true;  // OpenSCAD makes nothing of "" or "  "
    layout.text = string(node, "text", "", 0);
    layout.size = number(node, "size", 10.0, 1);
    layout.spacing = number(node, "spacing", 1.0);
    // OpenSCAD's FontCache::DEFAULT_FONT, for an empty name.
    layout.font = string(node, "font", "", 2);
    if (layout.font.find_first_not_of(" \t") == std::string::npos)
      layout.font = "Liberation Sans:style=Regular";
    // OpenSCAD takes a value it does not know for left and baseline.
    const std::string h = string(node, "halign", "left"), v = string(node, "valign", "baseline");
    using H = TextLayout::HAlign;
    using V = TextLayout::VAlign;
    layout.halign = h == "right" ? H::Right : h == "center" ? H::Center : H::Left;
    layout.valign = v == "top"      ? V::Top
                    : v == "center" ? V::Center
                    : v == "bottom" ? V::Bottom
                                    : V::Baseline;
    using D = TextLayout::Direction;
    const std::string d = string(node, "direction", "ltr");
    layout.direction = d == "rtl"   ? D::RightToLeft
                       : d == "ttb" ? D::TopToBottom
                       : d == "btt" ? D::BottomToTop
                                    : D::LeftToRight;
    layout.language = string(node, "language", "en");
    layout.script = string(node, "script", "");
    if (options_.facets == CsgFacets::OpenScad) {
      // As OpenSCAD 2021.01 draws a glyph's curves: per curve, the sides
      // of a circle of radius `size` over 8, plus 1, chords (at least 2).
      const OpenScadResolution res = resolution(node);
      layout.curveSegments =
          std::max(openscadFragments(layout.size, res.fn, res.fa, res.fs) / 8 + 1, 2);
    }
    RegionPtr region;
    try {
      region = textRegion(layout);
    } catch (const std::invalid_argument& e) {
      // Its message names the node ("text: ..."); so does ours.
      std::string message = e.what();
      if (message.starts_with("text: ")) message.erase(0, 6);
      throw NodeError(message);
    }
    if (!region) return {};
    return {nullptr, region};
  }

  Shape multmatrix(const CsgNode& node) {
    const CsgValue* m = find(node, "m", 0);
    if (!given(m) || m->kind != CsgValue::Kind::Vector || m->items.size() < 3)
      throw NodeError("needs a matrix of 3 or 4 rows of 4 numbers");
    glm::dmat4 matrix(1.0);
    for (std::size_t r = 0; r < std::min<std::size_t>(m->items.size(), 4); ++r) {
      std::vector<double> row = numbers(m->items[r], "a row of the matrix");
      if (row.size() != 4) throw NodeError("a row of the matrix must have 4 numbers");
      for (int c = 0; c < 4; ++c) {
        if (!std::isfinite(row[c])) throw NodeError("the matrix must be finite");
        matrix[c][r] = row[c];
      }
    }
    Shape s = booleanOf(node, Boolean::Op::Union);
    if (s.solid) return {s.solid->transformed(Affine::fromMatrix(matrix)), nullptr};
    if (s.region) {
      // A map of the plane z = 0 onto itself keeps a region a region.
      if (matrix[2][0] != 0.0 || matrix[2][1] != 0.0 || matrix[0][2] != 0.0 ||
          matrix[1][2] != 0.0 || matrix[3][2] != 0.0)
        throw NodeError("moves a 2D shape out of the plane z = 0; extrude it first");
      Affine2 map;
      map.linear = dmat2(matrix[0][0], matrix[0][1], matrix[1][0], matrix[1][1]);
      map.offset = dvec2(matrix[3][0], matrix[3][1]);
      const double det = map.linear[0][0] * map.linear[1][1] - map.linear[1][0] * map.linear[0][1];
      if (!(std::abs(det) > 0.0)) throw NodeError("the matrix squashes the 2D shape flat");
      return {nullptr, s.region->transformed(map)};
    }
    return s;
  }

  Shape color(const CsgNode& node) {
    Shape s = booleanOf(node, Boolean::Op::Union);
    if (!s.solid) return s;  // regions are shown in their own colour
    const CsgValue* c = find(node, "c", 0);
    if (!given(c)) return s;
    auto material = std::make_shared<Material>();
    double alpha = number(node, "alpha", 1.0);
    if (c->kind == CsgValue::Kind::String) {
      material->color = parseColor(c->text, "color");
    } else {
      std::vector<double> rgba = numbers(*c, "the colour");
      if (rgba.size() < 3) throw NodeError("the colour must have 3 or 4 numbers");
      dvec3 srgb(rgba[0], rgba[1], rgba[2]);
      for (int i = 0; i < 3; ++i)
        if (!(srgb[i] >= 0.0 && srgb[i] <= 1.0))
          throw NodeError("the colour's components must be in [0, 1]");
      material->color = srgbToLinear(srgb);
      if (rgba.size() >= 4) alpha = rgba[3];
    }
    // OpenSCAD's alpha: what shows of the part; the rest lets light through.
    if (!(alpha >= 0.0 && alpha <= 1.0)) throw NodeError("alpha must be in [0, 1]");
    material->transparency = 1.0 - alpha;
    return {solidWithMaterial(s.solid, material), nullptr};
  }

  Shape cube(const CsgNode& node) {
    const dvec3 size = numberOrVector(node, "size", 3, dvec3(1.0), 0);
    // OpenSCAD makes nothing of a cube without volume.
    if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0)) return {};
    return {boxShape(size, boolean(node, "center", false)), nullptr};
  }

  Shape sphere(const CsgNode& node) {
    const double r = number(node, "r", 1.0, 0);
    if (!(r > 0.0)) return {};
    if (int n = polygonSides(node, r)) return {ringSolid(sphereRings(r, n), n), nullptr};
    return {sphereShape(r, std::nullopt), nullptr};
  }

  // OpenSCAD's sphere: (n + 1) / 2 rings of n points, at the middles of
  // equal steps of latitude.
  static std::vector<dvec2> sphereRings(double r, int n) {
    const int rings = (n + 1) / 2;
    std::vector<dvec2> out;  // (radius, z), top down
    for (int i = 0; i < rings; ++i) {
      const dvec2 polar = unitCircleDegrees(180.0 * (i + 0.5) / rings);
      out.push_back({r * polar.y, r * polar.x});
    }
    return out;
  }

  // The polyhedron through rings of n points (radius, z) from the top down,
  // each at the angles 360°·j/n, a ring of radius 0 a single point: caps at
  // the first and the last ring, quads (triangles at a point) between.
  static SolidPtr ringSolid(const std::vector<dvec2>& rings, int n) {
    requireOpenScadTriangles(2.0 * double(n) * double(rings.size()));
    std::vector<dvec3> points;
    std::vector<std::size_t> first;
    for (const dvec2& ring : rings) {
      first.push_back(points.size());
      if (ring.x == 0.0) {
        points.push_back({0.0, 0.0, ring.y});
        continue;
      }
      for (int j = 0; j < n; ++j) {
        const dvec2 corner = ring.x * unitCircleDegrees(360.0 * j / n);
        points.push_back({corner.x, corner.y, ring.y});
      }
    }
    auto at = [&](std::size_t ring, int j) -> std::int64_t {
      return std::int64_t(rings[ring].x == 0.0 ? first[ring] : first[ring] + j % n);
    };
    std::vector<std::vector<std::int64_t>> faces;
    // Counterclockwise seen from outside.
    if (rings.front().x != 0.0) {
      std::vector<std::int64_t> top;
      for (int j = 0; j < n; ++j) top.push_back(at(0, j));
      faces.push_back(top);
    }
    for (std::size_t k = 0; k + 1 < rings.size(); ++k)
      for (int j = 0; j < n; ++j) {
        std::vector<std::int64_t> face = {at(k, j), at(k + 1, j), at(k + 1, j + 1), at(k, j + 1)};
        face.erase(std::unique(face.begin(), face.end()), face.end());
        if (face.size() > 1 && face.front() == face.back()) face.pop_back();
        faces.push_back(face);
      }
    if (rings.back().x != 0.0) {
      std::vector<std::int64_t> bottom;
      for (int j = n - 1; j >= 0; --j) bottom.push_back(at(rings.size() - 1, j));
      faces.push_back(bottom);
    }
    return Primitive::create<MeshSolid>(points, faces);
  }

  Shape cylinder(const CsgNode& node) {
    const double h = number(node, "h", 1.0);
    double r1 = number(node, "r1", 1.0), r2 = number(node, "r2", 1.0);
    if (given(find(node, "r"))) r1 = r2 = number(node, "r", 1.0);
    if (!(h > 0.0) || !(r1 >= 0.0 && r2 >= 0.0) || (r1 == 0.0 && r2 == 0.0)) return {};
    const bool center = boolean(node, "center", false);
    const double z0 = center ? -h / 2.0 : 0.0;
    if (int n = polygonSides(node, std::max(r1, r2)))
      return {ringSolid({{r2, z0 + h}, {r1, z0}}, n), nullptr};
    CylinderParams p;
    p.h = h;
    p.r1 = r1;
    p.r2 = r2;
    p.center = center;
    return {cylinderShape("cylinder", p), nullptr};
  }

  Shape polyhedron(const CsgNode& node) {
    const CsgValue* pts = find(node, "points", 0);
    const CsgValue* faces = find(node, "faces", 1);
    if (!given(faces)) faces = find(node, "triangles");
    if (!given(pts) || !given(faces)) throw NodeError("needs points and faces");
    if (pts->kind != CsgValue::Kind::Vector || faces->kind != CsgValue::Kind::Vector)
      throw NodeError("points and faces must be vectors");
    std::vector<dvec3> points;
    for (const CsgValue& p : pts->items) {
      std::vector<double> xyz = numbers(p, "a point");
      if (xyz.size() != 3) throw NodeError("a point must have 3 numbers");
      points.push_back({xyz[0], xyz[1], xyz[2]});
    }
    return {Primitive::create<MeshSolid>(points, indexLists(*faces, "a face")), nullptr};
  }

  Shape square(const CsgNode& node) {
    const dvec3 size = numberOrVector(node, "size", 2, dvec3(1.0), 0);
    if (!(size.x > 0.0 && size.y > 0.0)) return {};
    return {nullptr, rectangleRegion("square", size.x, size.y, boolean(node, "center", false))};
  }

  Shape circle(const CsgNode& node) {
    const double r = number(node, "r", 1.0, 0);
    if (!(r > 0.0)) return {};
    if (int n = polygonSides(node, r)) return {nullptr, regularPolygonRegion(n, r, std::nullopt)};
    return {nullptr, circleRegion(r, std::nullopt)};
  }

  Shape polygon(const CsgNode& node) {
    const CsgValue* pts = find(node, "points", 0);
    if (!given(pts) || pts->kind != CsgValue::Kind::Vector)
      throw NodeError("needs points, a vector of [x, y]");
    std::vector<dvec2> points;
    for (const CsgValue& p : pts->items) {
      std::vector<double> xy = numbers(p, "a point");
      if (xy.size() < 2) throw NodeError("a point must have 2 numbers");
      points.push_back({xy[0], xy[1]});
    }
    std::vector<std::vector<std::size_t>> paths;
    if (const CsgValue* ps = find(node, "paths", 1); given(ps)) {
      if (ps->kind != CsgValue::Kind::Vector) throw NodeError("paths must be a vector");
      for (const std::vector<std::int64_t>& path : indexLists(*ps, "a path"))
        paths.emplace_back(path.begin(), path.end());
    }
    if (points.empty()) return {};
    return {nullptr, polygonRegion(points, paths)};
  }

  Shape linearExtrude(const CsgNode& node) {
    RegionPtr region = regionOfChildren(node);
    if (!region) return {};
    OpenScadLinearExtrude e;
    e.height = number(node, "height", 100.0, 0);
    if (!(e.height > 0.0)) return {};
    e.center = boolean(node, "center", false);
    e.twistDegrees = number(node, "twist", 0.0);
    e.scale = dvec2(numberOrVector(node, "scale", 2, dvec3(1.0)));
    SolidPtr exact =
        Primitive::create<LinearExtrusion>(region, e.height, e.center, e.twistDegrees, e.scale);
    // Without a twist and with one scale OpenSCAD's sides are the exact
    // ones (flat); a scale of 0 on one axis only has no closed polygons.
    const bool flatSides = e.twistDegrees == 0.0 && e.scale.x == e.scale.y;
    if (options_.facets != CsgFacets::OpenScad || flatSides ||
        (e.scale.x == 0.0) != (e.scale.y == 0.0))
      return {exact, nullptr};
    if (const double slices = number(node, "slices", 0.0); slices >= 1.0)
      e.slices = int(std::min(slices, 1e9));
    const SweepLoops loops = polygonsOf(*region, "linear_extrude");
    if (loops.empty()) return {};
    return {openscadLinearExtrusion(loops, e, resolution(node)), nullptr};
  }

  Shape rotateExtrude(const CsgNode& node) {
    RegionPtr region = regionOfChildren(node);
    if (!region) return {};
    double angle = number(node, "angle", 360.0);
    // OpenSCAD turns a negative angle the other way, and takes at most a turn.
    angle = std::clamp(angle, -360.0, 360.0);
    if (angle == 0.0) return {};
    // Where the sweep starts: OpenSCAD's start= (written by releases after
    // 2021.01), else +x; OpenSCAD 2021.01 starts a whole turn's polygons
    // on −x.
    double start = number(node, "start", 0.0);
    if (options_.facets == CsgFacets::OpenScad && !given(find(node, "start")) &&
        std::abs(angle) == 360.0)
      start = 180.0;
    // A profile wholly on the side x < 0 sweeps what its mirror image does,
    // half a turn on: OpenSCAD takes either side of the axis (not both).
    if (region->bounds().lo.x < 0.0 && region->bounds().hi.x <= 0.0) {
      region = region->transformed(Affine2{dmat2(-1.0, 0.0, 0.0, 1.0), dvec2(0.0)});
      start += 180.0;
    }
    SolidPtr solid = Primitive::create<Revolution>(region, std::abs(angle));
    if (options_.facets == CsgFacets::OpenScad) {
      const SweepLoops loops = polygonsOf(*region, "rotate_extrude");
      if (loops.empty()) return {};
      solid = openscadRevolution(loops, std::abs(angle), resolution(node));
    }
    if (angle < 0.0) solid = solid->transformed(Affine::mirror(dvec3(0.0, 1.0, 0.0)));
    if (start != 0.0) solid = solid->transformed(rotationDegrees(start, dvec3(0.0, 0.0, 1.0)));
    return {solid, nullptr};
  }

  // The region as the polygons OpenSCAD sweeps: evaluated, what arcs are
  // left (rounded offsets) within a hundred times the region's evaluation
  // tolerance (10⁻⁵ of its size; letters' curves are OpenSCAD's chords
  // already), points within 10⁻⁷ of that of the axis on it; none for a
  // region without area.
  static SweepLoops polygonsOf(const Region& region, const char* kind) {
    const double tol = 100.0 * evaluationTolerance(region);
    SweepLoops loops;
    try {
      loops = sweepLoops(region, tol, kind);
    } catch (const std::invalid_argument&) {
      return {};  // OpenSCAD makes nothing of it
    }
    for (auto& loop : loops)
      for (dvec2& u : loop)
        if (std::abs(u.x) <= 1e-7 * tol) u.x = 0.0;
    return loops;
  }

  Shape offset(const CsgNode& node) {
    RegionPtr region = regionOfChildren(node);
    if (!region) return {};
    const CsgValue* r = find(node, "r");
    const double delta = number(node, "delta", 1.0);
    Profile result;
    if (given(r) && r->kind == CsgValue::Kind::Number) {
      if (r->number == 0.0) return {nullptr, region};
      result = offsetRounded(*region, r->number, evaluationTolerance(*region));
    } else {
      if (delta == 0.0) return {nullptr, region};
      result = offsetDelta(*region, delta, boolean(node, "chamfer", false),
                           evaluationTolerance(*region));
    }
    if (result.loops.empty()) return {};
    return {nullptr, Region::leaf(std::move(result))};
  }

  // The section by z = 0 or the shadow of the children's union: a region
  // taken from their mesh (export/solid_projection.h).
  Shape projection(const CsgNode& node) {
    Shape s = booleanOf(node, Boolean::Op::Union);
    if (s.empty()) return {};
    if (s.region) throw NodeError("takes solids, not 2D shapes");
    if (!options_.project) throw NodeError("this program cannot project solids");
    Profile flat = options_.project(s.solid, boolean(node, "cut", false));
    if (flat.loops.empty()) return {};
    return {nullptr, Region::leaf(std::move(flat))};
  }

  Shape resize(const CsgNode& node) {
    Shape s = booleanOf(node, Boolean::Op::Union);
    if (s.empty()) return s;
    const dvec3 size = numberOrVector(node, "newsize", 3, dvec3(0.0), 0);
    std::array<bool, 3> autoAxes{false, false, false};
    if (const CsgValue* a = find(node, "auto", 1); given(a)) {
      if (a->kind == CsgValue::Kind::Boolean) autoAxes.fill(a->boolean);
      if (a->kind == CsgValue::Kind::Vector)
        for (std::size_t i = 0; i < std::min<std::size_t>(3, a->items.size()); ++i)
          autoAxes[i] = a->items[i].kind == CsgValue::Kind::Boolean
                            ? a->items[i].boolean
                            : a->items[i].kind == CsgValue::Kind::Number && a->items[i].number;
    }
    if (s.solid)
      return {s.solid->transformed(
                  Affine::scaling(resizeFactors(tightBounds(*s.solid), size, autoAxes))),
              nullptr};
    return {nullptr, s.region->transformed(
                         regionResizeMap(*s.region, dvec2(size), {autoAxes[0], autoAxes[1]}))};
  }

  Shape hullOf(const CsgNode& node) {
    std::vector<Shape> shapes = children(node);
    if (shapes.empty()) return {};
    if (std::vector<SolidPtr> solids = solidsOf(shapes); !solids.empty())
      return {hullShape(solids), nullptr};
    std::vector<RegionPtr> regions;
    for (const Shape& s : shapes) regions.push_back(s.region);
    double tol = 1e300;
    for (const RegionPtr& r : regions) tol = std::min(tol, evaluationTolerance(*r));
    Profile result = hull(regions, tol);
    if (result.loops.empty()) return {};
    return {nullptr, Region::leaf(std::move(result))};
  }

  // The solids of children that are all solids; none when they are all
  // regions; an error when they are both.
  static std::vector<SolidPtr> solidsOf(const std::vector<Shape>& shapes) {
    std::vector<SolidPtr> solids;
    for (const Shape& s : shapes)
      if (s.solid) solids.push_back(s.solid);
    if (!solids.empty() && solids.size() != shapes.size())
      throw NodeError("mixes 2D and 3D children; extrude the 2D ones first");
    return solids;
  }

  Shape minkowskiOf(const CsgNode& node) {
    std::vector<Shape> shapes = children(node);
    if (shapes.empty()) return {};
    std::vector<SolidPtr> solids = solidsOf(shapes);
    if (!solids.empty())
      return {solids.size() == 1 ? solids.front() : minkowskiShape(solids), nullptr};
    RegionPtr sum = shapes.front().region;
    for (std::size_t i = 1; i < shapes.size(); ++i) {
      const double tol =
          std::min(evaluationTolerance(*sum), evaluationTolerance(*shapes[i].region));
      Profile result = minkowskiSum(sum, shapes[i].region, tol);
      if (result.loops.empty()) return {};
      sum = Region::leaf(std::move(result));
    }
    return {nullptr, sum};
  }

  Shape importFile(const CsgNode& node) {
    const CsgValue* f = find(node, "file", 0);
    if (!given(f) || f->kind != CsgValue::Kind::String) throw NodeError("needs file=\"...\"");
    std::string ext = std::filesystem::path(f->text).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".dxf") return {nullptr, importDxf(node, f->text)};
    if (ext == ".svg") return {nullptr, importSvg(node, f->text)};
    if (ext != ".stl" && ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".3mf")
      throw NodeError(f->text + ": not a file csgray reads (STL, OFF, OBJ, PLY, 3MF, DXF, SVG)");
    if (!options_.loadMesh) throw NodeError("this program cannot read mesh files");
    SolidPtr solid = meshShape(options_.loadMesh(resolved(f->text)), f->text);
    const double scale = number(node, "scale", 1.0);
    if (scale != 1.0) {
      if (!(scale > 0.0) || !std::isfinite(scale)) throw NodeError("scale must be > 0");
      solid = solid->transformed(Affine::scaling(dvec3(scale)));
    }
    return {solid, nullptr};
  }

  // The path of a file a node names, by the options' rule.
  std::string resolved(const std::string& name) const {
    if (!options_.resolveFile) throw NodeError("this program cannot read files");
    try {
      return options_.resolveFile(name);
    } catch (const std::invalid_argument& e) {
      // The resolver's message names the node ("import: ..."); so does ours.
      std::string message = e.what();
      if (message.starts_with("import: ")) message.erase(0, 8);
      throw NodeError(message);
    }
  }

  // import(file="x.dxf", layer=, origin=, scale=): its arcs exact, or
  // OpenSCAD's polygons of them from the node's $fn, $fa and $fs.
  RegionPtr importDxf(const CsgNode& node, const std::string& name) {
    DxfOptions dxf;
    if (const CsgValue* layer = find(node, "layer"); given(layer)) {
      if (layer->kind != CsgValue::Kind::String) throw NodeError("layer must be a string");
      dxf.layer = layer->text;
    }
    dxf.origin = dvec2(numberOrVector(node, "origin", 2, dvec3(0.0)));
    dxf.scale = number(node, "scale", 1.0);
    polygonSides(node, 1.0);  // checks $fa and $fs
    dxf.fragments = [this, &node](double r) { return polygonSides(node, r); };
    return readDxf(readInputFile(resolved(name), name, kMaxFileBytes), name, dxf);
  }

  // import(file="x.svg", id=, dpi=, center=): its curves exact, or
  // OpenSCAD's polygons of them (40-gons, whatever $fn says). OpenSCAD
  // 2021.01 reads no layer, origin or scale of an SVG file (its .csg files
  // write them all the same), so neither does this.
  RegionPtr importSvg(const CsgNode& node, const std::string& name) {
    SvgOptions svg;
    svg.id = string(node, "id", "");
    svg.dpi = number(node, "dpi", 72.0);
    if (!(svg.dpi >= 0.001)) throw NodeError("dpi must be a number >= 0.001");
    svg.center = boolean(node, "center", false);
    svg.openscadPolygons = options_.facets == CsgFacets::OpenScad;
    return readSvg(readInputFile(resolved(name), name, kMaxFileBytes), name, svg);
  }

  // surface(file=, center=, invert=): a height map (scene/height_map.h).
  Shape surface(const CsgNode& node) {
    const CsgValue* f = find(node, "file", 0);
    if (!given(f) || f->kind != CsgValue::Kind::String) throw NodeError("needs file=\"...\"");
    const HeightMap map = readHeightMap(resolved(f->text), f->text, boolean(node, "invert", false),
                                        options_.loadImage);
    try {
      return {heightMapSolid(map, boolean(node, "center", false)), nullptr};
    } catch (const std::invalid_argument& e) {
      throw NodeError(f->text + ": " + e.what());
    }
  }

  const std::string& file_;
  std::shared_ptr<const std::string> source_;  // file_, for solids' SourceLine
  const CsgImportOptions& options_;
  std::unordered_map<std::string, Shape> made2D_;  // by csgNodeKey
  // The parameters each node's making has asked for, until it is made.
  mutable std::unordered_map<const CsgNode*, std::set<std::string>> read_;
};

}  // namespace

CsgModel importCsg(const std::string& text, const std::string& fileName,
                   const CsgImportOptions& options) {
  return Importer(fileName, options).model(parseCsg(text, fileName));
}

CsgModel importCsgFile(const std::string& path, const CsgImportOptions& options) {
  InputFile file(path);
  if (!file.problem().empty()) throw CsgError(path + ": cannot open: " + file.problem());
  std::string text;
  if (!file.readUpTo(text, kMaxFileBytes + 1))
    throw CsgError(path + ": cannot read: " + file.problem());
  if (text.size() > kMaxFileBytes)
    throw CsgError(path + ": the file is larger than " + std::to_string(kMaxFileBytes >> 20) +
                   " MiB");
  return importCsg(text, path, options);
}

}  // namespace csgray::detail
