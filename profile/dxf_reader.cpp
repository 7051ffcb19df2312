#include "profile/dxf_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>

#include "engine/degrees.h"
#include "engine/printable_token.h"
#include "profile/b_spline.h"
#include "profile/region_evaluation.h"

namespace csgray::detail {

namespace {

using std::numbers::pi;

// One group of the file: a code line and the value line after it (the
// DXF Reference's "group code and value"), at the line of its code.
struct Group {
  int code = 0;
  std::string_view value;
  int line = 0;
};

// An entity, table entry or section marker: the value of its group 0 and
// the groups up to the next group 0.
struct Record {
  std::string_view type;
  int line = 0;
  std::vector<Group> groups;
};

std::string_view trimmed(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// Annotations and construction aids: they draw no outline, so they are
// left out, as OpenSCAD leaves them out.
const std::set<std::string_view> kAnnotations = {
    "DIMENSION",   "TEXT",      "MTEXT",      "POINT",     "HATCH", "ATTRIB", "ATTDEF",
    "VIEWPORT",    "LEADER",    "MLEADER",    "RAY",       "XLINE", "IMAGE",  "WIPEOUT",
    "MULTILEADER", "TOLERANCE", "ACAD_TABLE", "OLE2FRAME", "SHAPE", "REGION"};

// A block (BLOCKS section) or the drawing itself (ENTITIES section): its
// edges in its own coordinates and the blocks it inserts.
struct Drawing {
  struct Insert {
    std::string block;
    Affine2 map;  // block coordinates (less the block's base point) to ours
    // An array of copies (MINSERT): columns × rows, each moved by
    // column·columnStep + row·rowStep from the first.
    int columns = 1, rows = 1;
    dvec2 columnStep{0.0}, rowStep{0.0};
    int line = 0;
  };
  std::vector<ProfileEdge> edges;
  std::vector<Insert> inserts;
  dvec2 base{0.0};
};

// A POLYLINE's vertices, read from the VERTEX entities up to its SEQEND.
struct OpenPolyline {
  bool active = false;
  bool drawn = false;  // on the layer read
  bool closed = false;
  bool mirrored = false;
  int line = 0;
  std::vector<dvec2> points;
  std::vector<double> bulges;
  Drawing* into = nullptr;
};

constexpr int kMaxBlockDepth = 32;
// Edges a drawing may make, and blocks it may insert, the copies INSERT
// makes included: a few blocks that each insert the one before ten times
// would otherwise make billions.
constexpr std::size_t kMaxEdges = 200000;
constexpr std::size_t kMaxInserts = 1000000;

class DxfReader {
 public:
  DxfReader(const std::string& fileName, const DxfOptions& options)
      : file_(fileName), options_(options) {}

  RegionPtr read(const std::string& text) {
    std::vector<Record> all = records(text);
    enum class Section { None, Blocks, Entities, Other } section = Section::None;
    std::string sectionName;
    bool sawEntities = false;
    Drawing* block = nullptr;
    for (const Record& r : all) {
      if (r.type == "EOF") break;
      if (r.type == "SECTION") {
        if (section != Section::None)
          fail(r.line, "a SECTION inside the " + sectionName + " section (its ENDSEC is missing)");
        sectionName = std::string(valueOf(r, 2));
        section = sectionName == "BLOCKS"     ? Section::Blocks
                  : sectionName == "ENTITIES" ? Section::Entities
                                              : Section::Other;
        sawEntities |= section == Section::Entities;
        continue;
      }
      if (r.type == "ENDSEC") {
        if (polyline_.active) fail(polyline_.line, "POLYLINE without its SEQEND");
        section = Section::None;
        block = nullptr;
        continue;
      }
      if (section == Section::Blocks) {
        if (r.type == "BLOCK") {
          block = &blocks_[std::string(valueOf(r, 2))];
          block->base = point(r, 10, 20);
        } else if (r.type == "ENDBLK") {
          block = nullptr;
        } else if (block) {
          entity(r, *block, true);
        }
      } else if (section == Section::Entities) {
        entity(r, drawing_, false);
      }
    }
    if (section != Section::None)
      fail(all.empty() ? 1 : lastLine_,
           "the file ends inside the " + sectionName + " section (is it cut short?)");
    if (!sawEntities)
      throw std::invalid_argument(file_ + ": not a DXF drawing (no ENTITIES section)");

    // The drawing's points p become (p − origin) · scale.
    Affine2 map;
    map.linear = dmat2(options_.scale);
    map.offset = -options_.origin * options_.scale;
    std::vector<ProfileEdge> edges;
    std::size_t inserted = 0;
    collect(drawing_, map, 0, edges, inserted);
    Profile profile = joined(edges);
    if (profile.loops.empty()) {
      std::string which = options_.layer.empty()
                              ? "the drawing"
                              : "layer \"" + printableToken(options_.layer, 40) + "\"";
      // Names as the file has them, each cut short, the first ten only: the
      // message stays one line of a terminal's width or a few.
      constexpr std::size_t kShownLayers = 10;
      std::string layers;
      std::size_t shown = 0;
      for (const std::string& l : layers_)
        if (shown++ < kShownLayers) layers += (layers.empty() ? "" : ", ") + printableToken(l, 40);
      if (layers_.size() > kShownLayers)
        layers += " and " + std::to_string(layers_.size() - kShownLayers) + " more";
      throw std::invalid_argument(file_ + ": " + which + " draws no closed outline" +
                                  (layers.empty() ? "" : " (its layers: " + layers + ")"));
    }
    return Region::leaf(std::move(profile));
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(line) + ": " + what);
  }

  // ---- Groups and records --------------------------------------------------

  std::vector<Record> records(const std::string& text) {
    std::vector<Record> out;
    std::size_t at = 0;
    int line = 0;
    auto nextLine = [&](std::string_view& s) {
      if (at >= text.size()) return false;
      std::size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      s = trimmed(std::string_view(text).substr(at, end - at));
      at = end + 1;
      ++line;
      return true;
    };
    std::string_view codeText, value;
    while (nextLine(codeText)) {
      const int codeLine = line;
      if (codeText.empty() && at >= text.size()) break;  // a last empty line
      int code = 0;
      auto [end, error] = std::from_chars(codeText.data(), codeText.data() + codeText.size(), code);
      if (error != std::errc() || end != codeText.data() + codeText.size())
        fail(codeLine, "expected a group code (a whole number), found '" +
                           printableToken(codeText, 40) + "'");
      if (!nextLine(value)) fail(codeLine, "group code " + std::to_string(code) + " has no value");
      lastLine_ = line;
      if (code == 999) continue;  // a comment
      if (code == 0) {
        out.push_back({value, codeLine, {}});
      } else if (!out.empty()) {
        out.back().groups.push_back({code, value, codeLine});
      }
    }
    return out;
  }

  const Group* find(const Record& r, int code) const {
    for (const Group& g : r.groups)
      if (g.code == code) return &g;
    return nullptr;
  }

  std::string_view valueOf(const Record& r, int code) const {
    const Group* g = find(r, code);
    return g ? g->value : std::string_view();
  }

  double number(const Group& g) const {
    double v = 0.0;
    std::string_view s = g.value;
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (error != std::errc() || end != s.data() + s.size() || s.empty() || std::isnan(v))
      fail(g.line + 1, "expected a number for group code " + std::to_string(g.code) + ", found '" +
                           printableToken(g.value, 40) + "'");
    if (!std::isfinite(v) || std::abs(v) > 1e15)
      fail(g.line + 1,
           "the number " + printableToken(g.value, 40) + " is too large (at most 1e15 either way)");
    return v;
  }

  double number(const Record& r, int code, double fallback) const {
    const Group* g = find(r, code);
    return g ? number(*g) : fallback;
  }

  // A count of copies (an INSERT's columns or rows): a whole number, by
  // default 1; 0, as some writers put it for no array, is 1 too. (Past
  // kMaxInserts, collect stops at the limit.)
  int count(const Record& r, int code) const {
    const Group* g = find(r, code);
    if (!g) return 1;
    const double v = number(*g);
    if (!(v >= 0.0) || v != std::floor(v))
      fail(g->line + 1, "group code " + std::to_string(code) +
                            ": a count of copies must be a whole number, found " +
                            printableToken(g->value, 40));
    return int(std::clamp(v, 1.0, double(kMaxInserts) + 1.0));
  }

  dvec2 point(const Record& r, int xCode, int yCode) const {
    return {number(r, xCode, 0.0), number(r, yCode, 0.0)};
  }

  // ---- Entities ------------------------------------------------------------

  // The entity's extrusion direction (group 230) points down: its object
  // coordinates run with x mirrored (the DXF Reference's "arbitrary axis
  // algorithm" for the normal (0, 0, −1)).
  bool mirrored(const Record& r) const { return number(r, 230, 1.0) < 0.0; }

  void entity(const Record& r, Drawing& into, bool inBlock) {
    // A POLYLINE's vertices carry layers of their own; its layer decides.
    if (r.type == "VERTEX") {
      if (!polyline_.active) fail(r.line, "a VERTEX outside a POLYLINE");
      // A spline's frame point is not on the curve; a mesh's face has no point.
      const int flags = int(number(r, 70, 0.0));
      if (flags & (16 | 128)) return;
      polyline_.points.push_back(point(r, 10, 20));
      polyline_.bulges.push_back(number(r, 42, 0.0));
      return;
    }
    if (r.type == "SEQEND") {
      if (!polyline_.active) return;  // the end of an INSERT's attributes
      if (polyline_.drawn) {
        std::vector<ProfileEdge> edges;
        addPolyline(polyline_.points, polyline_.bulges, polyline_.closed, inBlock, edges);
        add(edges, polyline_.mirrored, *polyline_.into);
      }
      polyline_ = {};
      return;
    }
    if (polyline_.active) fail(polyline_.line, "POLYLINE without its SEQEND");
    const std::string_view named = valueOf(r, 8);
    const std::string layer(named.empty() ? std::string_view("0") : named);
    bool drawn = true;
    if (!inBlock) {
      layers_.insert(layer);
      drawn = options_.layer.empty() || options_.layer == layer;
    }
    if (r.type == "POLYLINE") {
      const int flags = int(number(r, 70, 0.0));
      if (flags & (16 | 64)) fail(r.line, "POLYLINE meshes are not supported");
      polyline_ = {true, drawn, bool(flags & 1), mirrored(r), r.line, {}, {}, &into};
      return;
    }
    if (!drawn || kAnnotations.contains(r.type)) return;
    // In a block, sizes are the block's own: OpenSCAD counts an arc's
    // sides from its radius there unscaled.
    const double fragmentScale = inBlock ? 1.0 : options_.scale;
    std::vector<ProfileEdge> edges;
    if (r.type == "LINE") {
      const dvec2 a = point(r, 10, 20), b = point(r, 11, 21);
      if (a != b) edges.push_back(ProfileEdge::segment(a, b));
    } else if (r.type == "CIRCLE") {
      const double radius = positive(r, 40, "a CIRCLE's radius");
      addArc(ProfileEdge::arc(point(r, 10, 20), dmat2(radius), 0.0, 2.0 * pi),
             radius * fragmentScale, 0.0, 360.0, 360.0, edges);
    } else if (r.type == "ARC") {
      const double radius = positive(r, 40, "an ARC's radius");
      // Counterclockwise from the start angle to the end angle, in degrees.
      const double start = number(r, 50, 0.0);
      double end = number(r, 51, 0.0);
      while (end < start) end += 360.0;
      if (end > start)
        addArc(
            ProfileEdge::arc(point(r, 10, 20), dmat2(radius), start * pi / 180.0, end * pi / 180.0),
            radius * fragmentScale, start, end - start, 360.0, edges);
    } else if (r.type == "ELLIPSE") {
      ellipse(r, fragmentScale, edges);
    } else if (r.type == "LWPOLYLINE") {
      lightweightPolyline(r, inBlock, edges);
    } else if (r.type == "SPLINE") {
      spline(r, edges);
    } else if (r.type == "INSERT") {
      insert(r, into);
    } else {
      fail(r.line, printableToken(r.type, 40) +
                       " entities are not supported (LINE, LWPOLYLINE, POLYLINE, ARC, CIRCLE, "
                       "ELLIPSE, SPLINE and INSERT are)");
    }
    // Lines, ellipses and splines are given in world coordinates.
    const bool world = r.type == "ELLIPSE" || r.type == "LINE" || r.type == "SPLINE";
    add(edges, !world && mirrored(r), into);
  }

  double positive(const Record& r, int code, const std::string& what) const {
    const Group* g = find(r, code);
    const double v = g ? number(*g) : 0.0;
    if (!(v > 0.0)) fail(g ? g->line + 1 : r.line, what + " must be > 0");
    return v;
  }

  static void add(std::vector<ProfileEdge>& edges, bool mirror, Drawing& into) {
    Affine2 flip;
    flip.linear = dmat2(-1.0, 0.0, 0.0, 1.0);
    for (ProfileEdge& e : edges) into.edges.push_back(mirror ? e.transformed(flip) : e);
  }

  // The arc itself, or OpenSCAD's polygon of it: ceil(sides · |sweep| /
  // turn) chords with equal angles (its dxfdata.cc). The arc runs from
  // `start` by `sweep` in the file's own unit of angle, a whole `turn`
  // being 360 (degrees: its points exact at the quarter turns, as
  // OpenSCAD's cos_degrees makes them) or 2π, so that the count is
  // OpenSCAD's to the last bit.
  void addArc(ProfileEdge arc, double radius, double start, double sweep, double turn,
              std::vector<ProfileEdge>& out) const {
    auto at = [&](double angle) {
      return turn == 360.0 ? arc.center + arc.axes * unitCircleDegrees(angle) : arc.arcPoint(angle);
    };
    if (turn == 360.0 && std::abs(sweep) < 360.0) {
      arc.from = at(start);
      arc.to = at(start + sweep);
    }
    const int sides = options_.fragments ? options_.fragments(radius) : 0;
    if (sides <= 0) {
      out.push_back(arc);
      return;
    }
    const int n = std::max(1, int(std::ceil(sides * std::abs(sweep) / turn)));
    dvec2 previous = arc.from;
    for (int i = 1; i <= n; ++i) {
      const dvec2 p = i == n ? arc.to : at(start + sweep * i / n);
      out.push_back(ProfileEdge::segment(previous, p));
      previous = p;
    }
  }

  void ellipse(const Record& r, double fragmentScale, std::vector<ProfileEdge>& out) const {
    // The centre, the end of the major axis from the centre, the minor
    // axis's ratio to it, and the parameters (radians) where it starts and
    // ends, counterclockwise.
    const dvec2 center = point(r, 10, 20), major = point(r, 11, 21);
    const double ratio = positive(r, 40, "an ELLIPSE's axis ratio");
    if (!(glm::length(major) > 0.0)) fail(r.line, "an ELLIPSE's major axis is 0 long");
    const double start = number(r, 41, 0.0);
    double end = number(r, 42, 2.0 * pi);
    while (end < start) end += 2.0 * pi;
    if (!(end > start)) return;
    const dmat2 axes(major, ratio * dvec2(-major.y, major.x));
    addArc(ProfileEdge::arc(center, axes, start, end), glm::length(major) * fragmentScale, start,
           end - start, 2.0 * pi, out);
  }

  // A SPLINE by its degree (group 71), knots (40, in order), control
  // points (10/20) and their weights (41, when they differ: a rational
  // spline), as Bézier edges and arcs (profile/b_spline.h). A spline given
  // by fit points alone (11/21) leaves its curve to the program that drew
  // it: refused.
  void spline(const Record& r, std::vector<ProfileEdge>& out) const {
    BSpline s;
    s.degree = int(number(r, 71, 3.0));
    bool fitPoints = false;
    for (const Group& g : r.groups) {
      if (g.code == 40) s.knots.push_back(number(g));
      if (g.code == 41) s.weights.push_back(number(g));
      if (g.code == 10) s.controls.push_back({number(g), 0.0});
      if (g.code == 20 && !s.controls.empty()) s.controls.back().y = number(g);
      fitPoints |= g.code == 11;
    }
    if (s.controls.empty())
      fail(r.line, fitPoints ? "a SPLINE given by fit points only is not supported (give its "
                               "control points and knots)"
                             : "a SPLINE without control points");
    try {
      out = bSplineEdges(s);
    } catch (const std::invalid_argument& e) {
      fail(r.line, std::string("SPLINE: ") + e.what());
    }
  }

  void lightweightPolyline(const Record& r, bool inBlock, std::vector<ProfileEdge>& out) const {
    std::vector<dvec2> points;
    std::vector<double> bulges;
    for (const Group& g : r.groups) {
      if (g.code == 10) {
        points.push_back({number(g), 0.0});
        bulges.push_back(0.0);
      } else if (g.code == 20 && !points.empty()) {
        points.back().y = number(g);
      } else if (g.code == 42 && !points.empty()) {
        bulges.back() = number(g);
      }
    }
    addPolyline(points, bulges, int(number(r, 70, 0.0)) & 1, inBlock, out);
  }

  void addPolyline(const std::vector<dvec2>& points, const std::vector<double>& bulges, bool closed,
                   bool inBlock, std::vector<ProfileEdge>& out) const {
    const std::size_t n = points.size();
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
      addBulgedEdge(points[i], points[(i + 1) % n], bulges[i], inBlock, out);
  }

  // A polyline's edge from a to b: straight, or for a bulge b ≠ 0 the arc
  // of included angle θ = 4·atan(b), counterclockwise for b > 0 (the DXF
  // Reference, LWPOLYLINE group 42). Its centre is off the chord's middle
  // along the chord's left normal by (d/2)·cot(θ/2), and
  // cot(θ/2) = (1 − b²) / (2b) since b = tan(θ/4).
  void addBulgedEdge(const dvec2& a, const dvec2& b, double bulge, bool inBlock,
                     std::vector<ProfileEdge>& out) const {
    if (a == b) return;
    if (bulge == 0.0) {
      out.push_back(ProfileEdge::segment(a, b));
      return;
    }
    const dvec2 chord = b - a;
    const double d = glm::length(chord);
    const dvec2 normal = dvec2(-chord.y, chord.x) / d;
    const dvec2 center = 0.5 * (a + b) + normal * (0.5 * d * (1.0 - bulge * bulge) / (2.0 * bulge));
    const double radius = glm::length(a - center);
    const double theta = 4.0 * std::atan(bulge);
    const double angle0 = std::atan2(a.y - center.y, a.x - center.x);
    ProfileEdge arc = ProfileEdge::arc(center, dmat2(radius), angle0, angle0 + theta);
    arc.from = a;
    arc.to = b;
    addArc(arc, radius * (inBlock ? 1.0 : options_.scale), angle0, theta, 2.0 * pi, out);
  }

  void insert(const Record& r, Drawing& into) const {
    Drawing::Insert insert;
    insert.block = std::string(valueOf(r, 2));
    insert.line = r.line;
    const dvec2 turn = unitCircleDegrees(number(r, 50, 0.0));
    const double c = turn.x, s = turn.y;
    const dvec2 scale(number(r, 41, 1.0), number(r, 42, 1.0));
    if (scale.x == 0.0 || scale.y == 0.0) fail(r.line, "an INSERT's scale is 0");
    // Scaled, turned, moved to the insertion point (in object coordinates,
    // mirrored with them).
    const dmat2 turned(c, s, -s, c);
    insert.map.linear = turned * dmat2(scale.x, 0.0, 0.0, scale.y);
    insert.map.offset = point(r, 10, 20);
    // An array: column and row counts (70, 71) and spacings (44, 45),
    // along the turned axes and not scaled (the DXF Reference's INSERT).
    insert.columns = count(r, 70);
    insert.rows = count(r, 71);
    insert.columnStep = turned * dvec2(number(r, 44, 0.0), 0.0);
    insert.rowStep = turned * dvec2(0.0, number(r, 45, 0.0));
    if (mirrored(r)) {
      Affine2 flip;
      flip.linear = dmat2(-1.0, 0.0, 0.0, 1.0);
      insert.map = insert.map.then(flip);
      insert.columnStep = flip.linear * insert.columnStep;
      insert.rowStep = flip.linear * insert.rowStep;
    }
    into.inserts.push_back(std::move(insert));
  }

  // The drawing's edges and those of the blocks it inserts, mapped.
  void collect(const Drawing& d, const Affine2& map, int depth, std::vector<ProfileEdge>& out,
               std::size_t& inserted) const {
    for (const ProfileEdge& e : d.edges) out.push_back(e.transformed(map));
    for (const Drawing::Insert& insert : d.inserts) {
      auto it = blocks_.find(insert.block);
      if (it == blocks_.end())
        fail(insert.line,
             "INSERT of the block \"" + insert.block + "\", which the file does not define");
      if (depth >= kMaxBlockDepth)
        fail(insert.line, "blocks nested deeper than " + std::to_string(kMaxBlockDepth) +
                              " (a block that inserts itself?)");
      Affine2 toBase;
      toBase.offset = -it->second.base;
      for (int row = 0; row < insert.rows; ++row)
        for (int column = 0; column < insert.columns; ++column) {
          if (out.size() > kMaxEdges || ++inserted > kMaxInserts)
            fail(insert.line, "more than " + std::to_string(kMaxEdges) + " edges or " +
                                  std::to_string(kMaxInserts) +
                                  " inserted blocks (with the copies INSERT makes)");
          Affine2 copy = insert.map;
          copy.offset += double(column) * insert.columnStep + double(row) * insert.rowStep;
          collect(it->second, toBase.then(copy).then(map), depth + 1, out, inserted);
        }
    }
  }

  // ---- Outlines ------------------------------------------------------------

  // The edges joined end to end into loops: ends closer than a millionth
  // of the drawing's size are one point (OpenSCAD joins within 0.001, its
  // GRID_COARSE). Paths that end where no edge goes on are started first
  // and closed with a segment, as OpenSCAD closes them; loops that enclose
  // nothing (a stray line) are left out.
  Profile joined(std::vector<ProfileEdge> edges) const {
    ProfileBounds box;
    for (const ProfileEdge& e : edges) {
      box.include(e.from);
      box.include(e.to);
      if (e.kind == ProfileEdge::Kind::Arc) {  // the box of its whole ellipse
        const dvec2 reach(std::abs(e.axes[0][0]) + std::abs(e.axes[1][0]),
                          std::abs(e.axes[0][1]) + std::abs(e.axes[1][1]));
        box.include(e.center - reach);
        box.include(e.center + reach);
      }
    }
    Profile profile;
    if (edges.empty()) return profile;
    const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
    const double tolerance = 1e-6 * size;
    if (!(tolerance > 0.0)) return profile;
    // The ends in cells of the tolerance's size: a match is in the cell of
    // the point or in one of its 8 neighbours.
    auto cellOf = [&](const dvec2& p) {
      return std::pair<std::int64_t, std::int64_t>(std::floor((p.x - box.lo.x) / tolerance),
                                                   std::floor((p.y - box.lo.y) / tolerance));
    };
    std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      cells[cellOf(edges[i].from)].push_back(2 * i);
      cells[cellOf(edges[i].to)].push_back(2 * i + 1);
    }
    std::vector<bool> used(edges.size(), false);
    auto endOf = [&](std::size_t end) { return end % 2 ? edges[end / 2].to : edges[end / 2].from; };
    // An unused edge's end within the tolerance of p, other than edge `not`'s.
    auto partner = [&](const dvec2& p, std::size_t notEdge) -> std::optional<std::size_t> {
      const auto [cx, cy] = cellOf(p);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          auto it = cells.find({cx + dx, cy + dy});
          if (it == cells.end()) continue;
          for (std::size_t end : it->second)
            if (!used[end / 2] && end / 2 != notEdge && glm::length(endOf(end) - p) <= tolerance)
              return end;
        }
      return std::nullopt;
    };
    auto follow = [&](std::size_t first, bool reversed) {
      ProfileLoop loop;
      used[first] = true;
      loop.edges.push_back(reversed ? reversedEdge(edges[first]) : edges[first]);
      while (auto end = partner(loop.edges.back().to, first)) {
        used[*end / 2] = true;
        const ProfileEdge& e = edges[*end / 2];
        loop.edges.push_back(*end % 2 ? reversedEdge(e) : e);
        loop.edges.back().from = loop.edges[loop.edges.size() - 2].to;
      }
      const dvec2 start = loop.edges.front().from;
      if (glm::length(loop.edges.back().to - start) <= tolerance)
        loop.edges.back().to = start;
      else
        loop.edges.push_back(ProfileEdge::segment(loop.edges.back().to, start));
      Profile one;
      one.loops.push_back(std::move(loop));
      if (std::abs(area(one)) > tolerance * size) profile.loops.push_back(std::move(one.loops[0]));
    };
    // Open paths first, from an end no other edge meets.
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (used[i]) continue;
      if (!partner(edges[i].from, i))
        follow(i, false);
      else if (!partner(edges[i].to, i))
        follow(i, true);
    }
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (!used[i]) follow(i, false);
    return profile;
  }

  static ProfileEdge reversedEdge(ProfileEdge e) {
    std::swap(e.from, e.to);
    std::swap(e.angle0, e.angle1);
    return e;
  }

  const std::string& file_;
  const DxfOptions& options_;
  std::map<std::string, Drawing> blocks_;
  Drawing drawing_;
  OpenPolyline polyline_;
  std::set<std::string> layers_;
  int lastLine_ = 1;
};

}  // namespace

RegionPtr readDxf(const std::string& text, const std::string& fileName, const DxfOptions& options) {
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw std::invalid_argument("scale must be > 0");
  if (!std::isfinite(options.origin.x) || !std::isfinite(options.origin.y))
    throw std::invalid_argument("origin must be finite");
  return DxfReader(fileName, options).read(text);
}

}  // namespace csgray::detail
