#include "profile/svg_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "engine/degrees.h"
#include "profile/bezier.h"
#include "profile/region_evaluation.h"
#include "profile/svg_path.h"
#include "profile/svg_stroke.h"
#include "profile/xml_reader.h"

namespace csgray::detail {

namespace {

using std::numbers::pi;

constexpr double kMmPerInch = 25.4;
constexpr int kMaxUseDepth = 32;
// Shapes a drawing may make, <use> copies included: a few <use> of groups
// of <use> would otherwise make billions.
constexpr std::size_t kMaxShapes = 100000;
// Elements visited, <use> copies included (copies of groups of nothing).
constexpr std::size_t kMaxVisits = 1000000;

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// The element's name without the "svg:" prefix a document may give
// SVG's elements.
std::string_view localName(const XmlElement& e) {
  std::string_view name = e.name;
  if (name.starts_with("svg:")) name.remove_prefix(4);
  return name;
}

Affine2 translation(const dvec2& d) {
  Affine2 m;
  m.offset = d;
  return m;
}

Affine2 scaling(const dvec2& s) {
  Affine2 m;
  m.linear = dmat2(s.x, 0.0, 0.0, s.y);
  return m;
}

// A length: a number and its unit ("" for none).
struct Length {
  double number = 0.0;
  std::string unit;
};

// What a shape is filled by, inherited from the elements around it.
struct Context {
  Affine2 map;           // the element's coordinates to the plane's
  bool evenOdd = true;   // fill-rule (even-odd where the file gives none, as OpenSCAD)
  bool visible = true;   // visibility
  bool selected = true;  // inside the element SvgOptions::id names
  int useDepth = 0;
};

// The edges of a shape's outlines.
using Loops = std::vector<ProfileLoop>;

double loopArea(const ProfileLoop& loop) {
  Profile one;
  one.loops.push_back(loop);
  return area(one);
}

// A point on the loop (the middle of its first edge), away from the
// corners where another loop may touch it.
dvec2 pointOn(const ProfileLoop& loop) {
  const ProfileEdge& e = loop.edges.front();
  switch (e.kind) {
    case ProfileEdge::Kind::Segment:
      return 0.5 * (e.from + e.to);
    case ProfileEdge::Kind::Arc:
      return e.arcPoint(0.5 * (e.angle0 + e.angle1));
    default:
      return bezierPoint(e, 0.5);
  }
}

// The points about which the loops wind a non-zero number of times (SVG
// 1.1, 11.3). Loops of segments only are filled exactly whatever they do
// (nonZeroFill). Loops with curves are taken not to cross one another:
// each loop's inside less the loops just inside it is a face whose winding
// number is the sum of the turns (±1) of the loop and those around it, and
// the faces with a winding number other than 0 are united.
RegionPtr nonZeroRegion(const Loops& loops) {
  bool curved = false;
  for (const ProfileLoop& loop : loops)
    for (const ProfileEdge& e : loop.edges) curved |= e.kind != ProfileEdge::Kind::Segment;
  if (!curved) {
    std::vector<std::array<dvec2, 2>> segments;
    for (const ProfileLoop& loop : loops)
      for (const ProfileEdge& e : loop.edges) segments.push_back({e.from, e.to});
    Profile filled = nonZeroFill(segments);
    return filled.loops.empty() ? nullptr : Region::leaf(std::move(filled));
  }
  const std::size_t n = loops.size();
  std::vector<double> areas(n);
  for (std::size_t i = 0; i < n; ++i) areas[i] = loopArea(loops[i]);
  // Each loop's parent: the smallest loop around it.
  std::vector<std::optional<std::size_t>> parent(n);
  for (std::size_t i = 0; i < n; ++i) {
    const dvec2 p = pointOn(loops[i]);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || std::abs(areas[j]) <= std::abs(areas[i])) continue;
      Profile around;
      around.loops.push_back(loops[j]);
      if (!around.contains(p)) continue;
      if (!parent[i] || std::abs(areas[j]) < std::abs(areas[*parent[i]])) parent[i] = j;
    }
  }
  std::vector<RegionPtr> faces;
  for (std::size_t i = 0; i < n; ++i) {
    if (areas[i] == 0.0) continue;
    int winding = 0;
    for (std::optional<std::size_t> k = i; k; k = parent[*k]) winding += areas[*k] > 0.0 ? 1 : -1;
    if (winding == 0) continue;
    Profile face;
    face.loops.push_back(loops[i]);
    for (std::size_t j = 0; j < n; ++j)
      if (parent[j] == i) face.loops.push_back(loops[j]);
    faces.push_back(Region::leaf(std::move(face)));
  }
  if (faces.empty()) return nullptr;
  return faces.size() == 1 ? faces.front() : Region::boolean(Region::Op::Union, std::move(faces));
}

// The corners after e.from of the polygon OpenSCAD 2021.01 draws of an
// edge (its libsvg's shape.cc and path.cc): a whole circle or ellipse as 40
// corners 9° apart, at (rx·sin a, ry·cos a) from its centre; an arc of a
// degrees as ⌊10·a/180⌋ + 4 chords, and a Bézier curve as 20, at equal
// steps of their parameters.
void appendOpenscadChords(const ProfileEdge& e, std::vector<dvec2>& corners) {
  const double sweep = std::abs(e.angle1 - e.angle0);
  if (e.kind == ProfileEdge::Kind::Segment) {
    corners.push_back(e.to);
  } else if (e.kind == ProfileEdge::Kind::Arc && sweep >= 2.0 * pi) {
    for (int i = 1; i <= 40; ++i) {
      const dvec2 turn = unitCircleDegrees(9.0 * i);
      corners.push_back(e.center + e.axes * dvec2(turn.y, turn.x));
    }
  } else {
    const bool arc = e.kind == ProfileEdge::Kind::Arc;
    const int n = arc ? int(sweep * 180.0 / pi * 10.0 / 180.0 + 4.0) : 20;
    for (int i = 1; i < n; ++i)
      corners.push_back(arc ? e.arcPoint(e.angle0 + (e.angle1 - e.angle0) * i / n)
                            : bezierPoint(e, double(i) / n));
    corners.push_back(e.to);
  }
}

// The loops as OpenSCAD's polygons of them.
Loops openscadPolygons(const Loops& loops) {
  Loops out;
  for (const ProfileLoop& loop : loops) {
    std::vector<dvec2> corners;
    for (const ProfileEdge& e : loop.edges) appendOpenscadChords(e, corners);
    ProfileLoop polygon;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const dvec2& from = corners[i == 0 ? corners.size() - 1 : i - 1];
      if (from != corners[i]) polygon.edges.push_back(ProfileEdge::segment(from, corners[i]));
    }
    if (!polygon.edges.empty()) out.push_back(std::move(polygon));
  }
  return out;
}

// What a shape draws: outlines it fills, and polylines whose strokes it
// outlines.
struct Drawn {
  Loops loops;
  std::vector<std::vector<dvec2>> strokes;
};

class SvgReader {
 public:
  SvgReader(const std::string& fileName, const SvgOptions& options)
      : file_(fileName), options_(options) {}

  RegionPtr read(std::string_view text) {
    const XmlElement root = readXml(text, file_);
    if (localName(root) != "svg")
      fail(root.line, "not an SVG drawing (its root element is <" + root.name + ">, not <svg>)");
    indexIds(root);
    if (!options_.id.empty() && !ids_.contains(options_.id))
      throw std::invalid_argument(file_ + ": no element has the id \"" + options_.id + "\"");
    Context context;
    context.map = pageMap(root);
    context.selected = options_.id.empty();
    element(root, context, true);
    if (shapes_.empty())
      throw std::invalid_argument(
          file_ + ": " +
          (options_.id.empty() ? "the drawing" : "the element \"" + options_.id + "\"") +
          " fills no closed outline");
    RegionPtr region =
        shapes_.size() == 1 ? shapes_.front() : Region::boolean(Region::Op::Union, shapes_);
    if (options_.center) {
      const ProfileBounds& box = region->bounds();
      region = region->transformed(translation(-0.5 * (box.lo + box.hi)));
    }
    return region;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(line) + ": " + what);
  }

  void indexIds(const XmlElement& e) {
    if (const XmlAttribute* id = e.attribute("id")) ids_.emplace(id->value, &e);
    for (const XmlElement& child : e.children) indexIds(child);
  }

  // ---- Attributes ----------------------------------------------------------

  // A presentation property: the style attribute's declaration wins over
  // the attribute of that name (SVG 1.1, 6.4).
  std::optional<std::string> property(const XmlElement& e, std::string_view name) const {
    if (const XmlAttribute* style = e.attribute("style")) {
      std::string_view s = style->value;
      std::optional<std::string> found;
      while (!s.empty()) {
        const std::size_t semicolon = s.find(';');
        const std::string_view declaration = s.substr(0, semicolon);
        s = semicolon == std::string_view::npos ? std::string_view() : s.substr(semicolon + 1);
        const std::size_t colon = declaration.find(':');
        if (colon == std::string_view::npos) continue;
        if (trimmed(declaration.substr(0, colon)) == name)
          found = trimmed(declaration.substr(colon + 1));
      }
      if (found) return found;
    }
    if (const XmlAttribute* a = e.attribute(name)) return trimmed(a->value);
    return std::nullopt;
  }

  std::vector<double> numbers(const XmlAttribute& a) const {
    try {
      return parseSvgNumbers(a.value);
    } catch (const std::invalid_argument& error) {
      fail(a.line, a.name + ": " + error.what());
    }
  }

  // A number and its unit, or nullopt when the text does not start with a
  // number.
  static std::optional<Length> splitLength(std::string_view text) {
    const std::string value = trimmed(text);
    const std::size_t end = svgNumberEnd(value, 0);
    if (end == 0) return std::nullopt;
    const std::optional<double> number = svgNumber(std::string_view(value).substr(0, end));
    if (!number) return std::nullopt;
    return Length{*number, trimmed(std::string_view(value).substr(end))};
  }

  std::optional<Length> length(const XmlElement& e, std::string_view name) const {
    const XmlAttribute* a = e.attribute(name);
    if (!a) return std::nullopt;
    const std::optional<Length> l = splitLength(a->value);
    if (!l) {
      // A number past the range (1e20) is not "not a length".
      const std::string value = trimmed(a->value);
      if (const std::size_t end = svgNumberEnd(value, 0); end > 0)
        fail(a->line,
             a->name + ": the number " + svgExcerpt(value.substr(0, end)) + " is out of range");
      fail(a->line, a->name + ": expected a length, found \"" + svgExcerpt(value) + "\"");
    }
    if (l->unit == "em" || l->unit == "ex")
      fail(a->line, a->name + ": lengths in " + l->unit +
                        " depend on a font; give them in mm, cm, in, pt, pc or px");
    if (l->unit != "" && l->unit != "px" && l->unit != "mm" && l->unit != "cm" && l->unit != "in" &&
        l->unit != "pt" && l->unit != "pc" && l->unit != "%")
      fail(a->line, a->name + ": \"" + svgExcerpt(l->unit) + "\" is not a unit of length");
    return l;
  }

  // A coordinate or size of a shape, in user units: a number, or in px.
  double userLength(const XmlElement& e, std::string_view name, double fallback) const {
    const std::optional<Length> l = length(e, name);
    if (!l) return fallback;
    if (!l->unit.empty() && l->unit != "px")
      fail(e.attribute(name)->line, std::string(name) +
                                        ": lengths inside the drawing are read in " +
                                        "user units (a number, or px), not in " + l->unit);
    return l->number;
  }

  // A length of the page in millimetres, as OpenSCAD reads it: px at 96
  // to the inch, numbers without a unit at the dpi given.
  double millimetres(const Length& l) const {
    if (l.unit == "mm") return l.number;
    if (l.unit == "cm") return 10.0 * l.number;
    if (l.unit == "in") return kMmPerInch * l.number;
    if (l.unit == "pt") return kMmPerInch * l.number / 72.0;
    if (l.unit == "pc") return kMmPerInch * l.number / 6.0;
    if (l.unit == "px") return kMmPerInch * l.number / 96.0;
    return kMmPerInch * l.number / options_.dpi;
  }

  // ---- Coordinate systems ---------------------------------------------------

  struct ViewBox {
    dvec2 origin{0.0}, size{0.0};
  };

  std::optional<ViewBox> viewBox(const XmlElement& e) const {
    const XmlAttribute* a = e.attribute("viewBox");
    if (!a) return std::nullopt;
    const std::vector<double> v = numbers(*a);
    if (v.size() != 4) fail(a->line, "viewBox: expected 4 numbers (x y width height)");
    if (!(v[2] > 0.0) || !(v[3] > 0.0)) fail(a->line, "viewBox: its width and height must be > 0");
    return ViewBox{{v[0], v[1]}, {v[2], v[3]}};
  }

  // The map of a viewBox onto a viewport of `size` by preserveAspectRatio
  // (SVG 1.1, 7.8): its scales, and the move that aligns it.
  Affine2 fitted(const XmlElement& e, const ViewBox& box, const dvec2& size) const {
    dvec2 scale = size / box.size;
    dvec2 align(0.0);
    std::string ratio = trimmed(property(e, "preserveAspectRatio").value_or("xMidYMid meet"));
    if (ratio.starts_with("defer")) ratio = trimmed(std::string_view(ratio).substr(5));
    const std::size_t space = ratio.find_first_of(" \t\r\n");
    const std::string how = ratio.substr(0, space);
    const std::string meetOrSlice =
        space == std::string::npos ? "meet" : trimmed(std::string_view(ratio).substr(space));
    if (how != "none") {
      const auto part = [&](std::size_t at) -> int {
        const std::string p = how.substr(at, 3);
        return p == "Min" ? 0 : p == "Mid" ? 1 : p == "Max" ? 2 : -1;
      };
      const int ax = how.size() == 8 && how[0] == 'x' && how[4] == 'Y' ? part(1) : -1;
      const int ay = how.size() == 8 && how[0] == 'x' && how[4] == 'Y' ? part(5) : -1;
      if (ax < 0 || ay < 0 || (meetOrSlice != "meet" && meetOrSlice != "slice")) {
        const XmlAttribute* a = e.attribute("preserveAspectRatio");
        fail(a ? a->line : e.line, "preserveAspectRatio: \"" + svgExcerpt(ratio) +
                                       "\" is not an alignment (xMidYMid meet, ...)");
      }
      const double s =
          meetOrSlice == "meet" ? std::min(scale.x, scale.y) : std::max(scale.x, scale.y);
      scale = dvec2(s);
      align = 0.5 * dvec2(ax, ay) * (size - s * box.size);
    }
    return translation(-box.origin).then(scaling(scale)).then(translation(align));
  }

  // The root's user units to the plane: into millimetres on the page by
  // its width, height and viewBox as OpenSCAD reads them, then mirrored
  // so that the page's bottom left corner is the origin and y points up.
  Affine2 pageMap(const XmlElement& root) const {
    const std::optional<ViewBox> box = viewBox(root);
    // A size in %, or none, is the viewBox's at the dpi (OpenSCAD's rule
    // for a page without a size).
    const auto side = [&](std::string_view name, double boxSide) {
      const std::optional<Length> l = length(root, name);
      const double whole = box ? kMmPerInch * boxSide / options_.dpi : 0.0;
      if (!l) return whole;
      if (l->unit == "%") return whole * l->number / 100.0;
      return millimetres(*l);
    };
    const double width = side("width", box ? box->size.x : 0.0);
    const dvec2 page(width, side("height", box ? box->size.y : 0.0));
    Affine2 toPage;
    if (box) toPage = fitted(root, *box, page);
    Affine2 flip;
    flip.linear = dmat2(1.0, 0.0, 0.0, -1.0);
    flip.offset = dvec2(0.0, page.y);
    return transform(root).then(toPage).then(flip);
  }

  // The element's transform attribute (SVG 1.1, 7.6): a list of matrix,
  // translate, scale, rotate, skewX and skewY, applied right to left.
  Affine2 transform(const XmlElement& e) const {
    const XmlAttribute* a = e.attribute("transform");
    Affine2 result;
    if (!a) return result;
    std::string_view s = a->value;
    std::size_t at = 0;
    while (true) {
      while (at < s.size() && (std::isspace(static_cast<unsigned char>(s[at])) || s[at] == ','))
        ++at;
      if (at >= s.size()) break;
      const std::size_t nameStart = at;
      while (at < s.size() && std::isalpha(static_cast<unsigned char>(s[at]))) ++at;
      const std::string name(s.substr(nameStart, at - nameStart));
      while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at]))) ++at;
      const std::size_t close = s.find(')', at);
      if (name.empty() || at >= s.size() || s[at] != '(' || close == std::string_view::npos)
        fail(a->line,
             "transform: expected matrix(...), translate(...), scale(...), rotate(...), "
             "skewX(...) or skewY(...), found \"" +
                 svgExcerpt(s.substr(nameStart)) + "\"");
      std::vector<double> v;
      try {
        v = parseSvgNumbers(s.substr(at + 1, close - at - 1));
      } catch (const std::invalid_argument& error) {
        fail(a->line, "transform: " + svgExcerpt(name) + ": " + error.what());
      }
      at = close + 1;
      const auto counts = [&](std::initializer_list<std::size_t> allowed) {
        if (std::find(allowed.begin(), allowed.end(), v.size()) == allowed.end())
          fail(a->line, "transform: " + name + " takes " +
                            (allowed.size() == 1 ? std::to_string(*allowed.begin())
                                                 : std::to_string(*allowed.begin()) + " or " +
                                                       std::to_string(*(allowed.end() - 1))) +
                            " numbers, not " + std::to_string(v.size()));
      };
      Affine2 m;
      if (name == "matrix") {
        counts({6});
        m.linear = dmat2(v[0], v[1], v[2], v[3]);
        m.offset = dvec2(v[4], v[5]);
      } else if (name == "translate") {
        counts({1, 2});
        m.offset = dvec2(v[0], v.size() > 1 ? v[1] : 0.0);
      } else if (name == "scale") {
        counts({1, 2});
        m.linear = dmat2(v[0], 0.0, 0.0, v.size() > 1 ? v[1] : v[0]);
      } else if (name == "rotate") {
        counts({1, 3});
        const dvec2 turn = unitCircleDegrees(v[0]);
        m.linear = dmat2(turn.x, turn.y, -turn.y, turn.x);
        if (v.size() == 3) {  // about (cx, cy): translate(c) rotate(a) translate(−c)
          const dvec2 c(v[1], v[2]);
          m.offset = c - m.linear * c;
        }
      } else if (name == "skewX" || name == "skewY") {
        counts({1});
        const dvec2 turn = unitCircleDegrees(v[0]);
        if (std::abs(turn.x) < 1e-12) fail(a->line, "transform: " + name + " of 90° is not a map");
        const double t = turn.y / turn.x;
        m.linear = name == "skewX" ? dmat2(1.0, 0.0, t, 1.0) : dmat2(1.0, t, 0.0, 1.0);
      } else {
        fail(a->line, "transform: \"" + svgExcerpt(name) + "\" is not a transform");
      }
      // The list reads left to right as nested frames: the rightmost map
      // applies to the points first.
      result = m.then(result);
    }
    return result;
  }

  // ---- Elements --------------------------------------------------------------

  void element(const XmlElement& e, Context context, bool root = false) {
    if (++visits_ > kMaxVisits)
      fail(e.line, "more than " + std::to_string(kMaxVisits) +
                       " elements to draw (with the copies <use> makes)");
    if (property(e, "display") == "none") return;
    if (const std::optional<std::string> v = property(e, "visibility"))
      context.visible = *v != "hidden" && *v != "collapse";
    if (const std::optional<std::string> rule = property(e, "fill-rule")) {
      if (*rule != "evenodd" && *rule != "nonzero" && *rule != "inherit") {
        const XmlAttribute* a = e.attribute("fill-rule");
        fail(a ? a->line : e.line,
             "fill-rule: \"" + svgExcerpt(*rule) + "\" is not evenodd or nonzero");
      }
      if (*rule != "inherit") context.evenOdd = *rule == "evenodd";
    }
    if (!options_.id.empty())
      if (const XmlAttribute* id = e.attribute("id"); id && id->value == options_.id)
        context.selected = true;
    const std::string_view name = localName(e);
    if (!root) context.map = transform(e).then(context.map);
    if (name == "svg" || name == "g" || name == "a" || name == "switch") {
      if (name == "svg" && !root) context.map = nestedViewport(e).then(context.map);
      for (const XmlElement& child : e.children) element(child, context);
    } else if (name == "use") {
      use(e, context);
    } else if (name == "path" || name == "rect" || name == "circle" || name == "ellipse" ||
               name == "polygon" || name == "polyline" || name == "line") {
      Drawn drawn = shape(e, name);
      Loops& loops = drawn.loops;
      if (options_.openscadPolygons) loops = openscadPolygons(loops);
      if (!context.selected || !context.visible) return;
      if (shapes_.size() + drawn.strokes.size() >= kMaxShapes)
        fail(e.line,
             "more than " + std::to_string(kMaxShapes) + " shapes (with the copies <use> makes)");
      if (std::abs(context.map.linear[0][0] * context.map.linear[1][1] -
                   context.map.linear[1][0] * context.map.linear[0][1]) == 0.0)
        return;  // flattened to a line or a point: no area
      if (!drawn.strokes.empty()) {
        const StrokeStyle style = strokeStyle(e);
        for (const std::vector<dvec2>& line : drawn.strokes)
          if (RegionPtr stroke = strokeRegion(line, style))
            shapes_.push_back(stroke->transformed(context.map));
      }
      if (loops.empty()) return;
      for (ProfileLoop& loop : loops)
        for (ProfileEdge& edge : loop.edges) edge = edge.transformed(context.map);
      if (context.evenOdd) {
        Profile profile;
        profile.loops = std::move(loops);
        shapes_.push_back(Region::leaf(std::move(profile)));
      } else if (RegionPtr filled = nonZeroRegion(loops)) {
        shapes_.push_back(filled);
      }
    }
    // Anything else draws nothing of its own: <defs>, <symbol> and the
    // like only through <use>, <text> and <image> not at all.
  }

  // A nested <svg>: its x and y, and its viewBox fitted to its width and
  // height (SVG 1.1, 7.9).
  Affine2 nestedViewport(const XmlElement& e) const {
    const dvec2 at(userLength(e, "x", 0.0), userLength(e, "y", 0.0));
    Affine2 map;
    if (const std::optional<ViewBox> box = viewBox(e)) {
      const dvec2 size(userLength(e, "width", box->size.x), userLength(e, "height", box->size.y));
      map = fitted(e, *box, size);
    }
    return map.then(translation(at));
  }

  // <use href="#id" x= y=>: the element drawn as if it stood here, moved by
  // (x, y) (SVG 1.1, 5.6); a <symbol> is drawn like a nested <svg>.
  void use(const XmlElement& e, Context context) {
    const XmlAttribute* href = e.attribute("href");
    if (!href) href = e.attribute("xlink:href");
    if (!href) return;
    if (!href->value.starts_with("#"))
      fail(href->line, "<use> of \"" + svgExcerpt(href->value) +
                           "\": only elements of this file (\"#id\") can be used");
    auto it = ids_.find(href->value.substr(1));
    if (it == ids_.end())
      fail(href->line,
           "<use> of \"" + svgExcerpt(href->value) + "\", which no element has as its id");
    if (context.useDepth >= kMaxUseDepth)
      fail(e.line, "<use> nested deeper than " + std::to_string(kMaxUseDepth) +
                       " (an element that uses itself?)");
    ++context.useDepth;
    context.map = translation({userLength(e, "x", 0.0), userLength(e, "y", 0.0)}).then(context.map);
    const XmlElement& target = *it->second;
    if (localName(target) == "symbol") {
      Context inner = context;
      inner.map = transform(target).then(context.map);
      if (const std::optional<ViewBox> box = viewBox(target)) {
        const dvec2 size(userLength(e, "width", box->size.x), userLength(e, "height", box->size.y));
        inner.map = fitted(target, *box, size).then(inner.map);
      }
      for (const XmlElement& child : target.children) element(child, inner);
      return;
    }
    element(target, context);
  }

  // ---- Shapes ----------------------------------------------------------------

  // The stroke OpenSCAD outlines: stroke-width of the element itself (not
  // inherited; 1 where it is missing or less than 0.01), its
  // stroke-linecap (square by default) and stroke-linejoin (miter).
  StrokeStyle strokeStyle(const XmlElement& e) const {
    StrokeStyle style;
    if (const std::optional<std::string> width = property(e, "stroke-width")) {
      const std::optional<Length> l = splitLength(*width);
      if (!l || (!l->unit.empty() && l->unit != "px")) {
        const XmlAttribute* a = e.attribute("stroke-width");
        fail(a ? a->line : e.line,
             "stroke-width: expected a number (user units), found \"" + svgExcerpt(*width) + "\"");
      }
      if (l->number >= 0.01) style.width = l->number;
    }
    const std::string cap = property(e, "stroke-linecap").value_or("");
    style.cap = cap == "butt"    ? StrokeStyle::Cap::Butt
                : cap == "round" ? StrokeStyle::Cap::Round
                                 : StrokeStyle::Cap::Square;
    const std::string join = property(e, "stroke-linejoin").value_or("");
    style.join = join == "bevel"   ? StrokeStyle::Join::Bevel
                 : join == "round" ? StrokeStyle::Join::Round
                                   : StrokeStyle::Join::Miter;
    return style;
  }

  Drawn shape(const XmlElement& e, std::string_view name) const {
    Drawn drawn;
    Loops& loops = drawn.loops;
    if (name == "path") {
      const XmlAttribute* d = e.attribute("d");
      if (!d) return drawn;
      std::vector<SvgSubpath> subpaths;
      try {
        subpaths = parseSvgPath(d->value);
      } catch (const std::invalid_argument& error) {
        fail(d->line, "<path> d: " + std::string(error.what()));
      }
      for (SvgSubpath& sub : subpaths) {
        const dvec2 start = sub.edges.front().from, end = sub.edges.back().to;
        // A subpath not closed by Z whose ends are more than 0.1 apart is a
        // stroke, as OpenSCAD takes it, its curves OpenSCAD's chords; one
        // whose ends are nearer is closed by a segment.
        if (!sub.closed && glm::length(end - start) > 0.1) {
          std::vector<dvec2>& line = drawn.strokes.emplace_back(1, start);
          for (const ProfileEdge& edge : sub.edges) appendOpenscadChords(edge, line);
          continue;
        }
        if (end != start) sub.edges.push_back(ProfileEdge::segment(end, start));
        loops.push_back({std::move(sub.edges)});
      }
    } else if (name == "rect") {
      rect(e, loops);
    } else if (name == "circle" || name == "ellipse") {
      const dvec2 c(userLength(e, "cx", 0.0), userLength(e, "cy", 0.0));
      const double rx = name == "circle" ? userLength(e, "r", 0.0) : userLength(e, "rx", 0.0);
      const double ry = name == "circle" ? rx : userLength(e, "ry", 0.0);
      if (rx < 0.0 || ry < 0.0) fail(e.line, "<" + std::string(name) + "> with a negative radius");
      if (rx > 0.0 && ry > 0.0)
        loops.push_back({{ProfileEdge::arc(c, dmat2(rx, 0.0, 0.0, ry), 0.0, 2.0 * pi)}});
    } else if (name == "polygon" || name == "polyline") {
      const XmlAttribute* a = e.attribute("points");
      const std::vector<double> v = a ? numbers(*a) : std::vector<double>();
      if (v.size() % 2) fail(a->line, "points: an odd count of numbers (x and y come in pairs)");
      std::vector<dvec2> points;
      for (std::size_t i = 0; i + 1 < v.size(); i += 2)
        if (points.empty() || points.back() != dvec2(v[i], v[i + 1]))
          points.push_back({v[i], v[i + 1]});
      // OpenSCAD outlines a polyline's stroke, even one that ends where it
      // starts.
      if (name == "polyline") {
        drawn.strokes.push_back(std::move(points));
        return drawn;
      }
      if (points.size() > 1 && points.front() == points.back()) points.pop_back();
      if (points.size() < 3) return drawn;
      ProfileLoop loop;
      for (std::size_t i = 0; i < points.size(); ++i)
        loop.edges.push_back(ProfileEdge::segment(points[i], points[(i + 1) % points.size()]));
      loops.push_back(std::move(loop));
    } else if (name == "line") {
      drawn.strokes.push_back({{userLength(e, "x1", 0.0), userLength(e, "y1", 0.0)},
                               {userLength(e, "x2", 0.0), userLength(e, "y2", 0.0)}});
    }
    return drawn;
  }

  // A rectangle, its corners rounded by quarters of the ellipse of radii
  // rx, ry: one given stands for both, and each is at most half the side
  // (SVG 1.1, 9.2).
  void rect(const XmlElement& e, Loops& loops) const {
    const double x = userLength(e, "x", 0.0), y = userLength(e, "y", 0.0);
    const double w = userLength(e, "width", 0.0), h = userLength(e, "height", 0.0);
    if (w < 0.0 || h < 0.0) fail(e.line, "<rect> with a negative width or height");
    if (w == 0.0 || h == 0.0) return;
    std::optional<double> rx, ry;
    if (e.attribute("rx")) rx = userLength(e, "rx", 0.0);
    if (e.attribute("ry")) ry = userLength(e, "ry", 0.0);
    if ((rx && *rx < 0.0) || (ry && *ry < 0.0)) fail(e.line, "<rect> with a negative rx or ry");
    const double rxUsed = std::min(rx.value_or(ry.value_or(0.0)), 0.5 * w);
    const double ryUsed = std::min(ry.value_or(rx.value_or(0.0)), 0.5 * h);
    ProfileLoop loop;
    if (rxUsed == 0.0 || ryUsed == 0.0) {
      const dvec2 corners[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
      for (int i = 0; i < 4; ++i)
        loop.edges.push_back(ProfileEdge::segment(corners[i], corners[(i + 1) % 4]));
    } else {
      // Counterclockwise in the plane of the numbers: the sides between
      // the corners' quarter arcs, centred rx, ry in from each corner.
      const dmat2 axes(rxUsed, 0.0, 0.0, ryUsed);
      const dvec2 centers[4] = {{x + w - rxUsed, y + ryUsed},
                                {x + w - rxUsed, y + h - ryUsed},
                                {x + rxUsed, y + h - ryUsed},
                                {x + rxUsed, y + ryUsed}};
      for (int i = 0; i < 4; ++i) {
        const double a0 = (i - 1) * 0.5 * pi;
        ProfileEdge arc = ProfileEdge::arc(centers[i], axes, a0, a0 + 0.5 * pi);
        const dvec2 ends[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        arc.from = centers[i] + axes * ends[(i + 3) % 4];
        arc.to = centers[i] + axes * ends[i % 4];
        if (!loop.edges.empty() && loop.edges.back().to != arc.from)
          loop.edges.push_back(ProfileEdge::segment(loop.edges.back().to, arc.from));
        loop.edges.push_back(arc);
      }
      if (loop.edges.back().to != loop.edges.front().from)
        loop.edges.push_back(ProfileEdge::segment(loop.edges.back().to, loop.edges.front().from));
    }
    loops.push_back(std::move(loop));
  }

  const std::string& file_;
  const SvgOptions& options_;
  std::map<std::string, const XmlElement*> ids_;
  std::vector<RegionPtr> shapes_;
  std::size_t visits_ = 0;
};

}  // namespace

RegionPtr readSvg(std::string_view text, const std::string& fileName, const SvgOptions& options) {
  if (!(options.dpi >= 0.001) || !std::isfinite(options.dpi))
    throw std::invalid_argument("dpi must be a number >= 0.001");
  return SvgReader(fileName, options).read(text);
}

}  // namespace csgray::detail
