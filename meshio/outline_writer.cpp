#include "meshio/outline_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "io/atomic_file.h"
#include "profile/bezier.h"

namespace csgray::detail {

namespace {

constexpr double kPi = std::numbers::pi;

std::string number(double x) {
  if (x == 0.0) x = 0.0;  // no "-0"
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

double degrees(double radians) { return radians * 180.0 / kPi; }

double determinant(const dmat2& m) { return m[0][0] * m[1][1] - m[1][0] * m[0][1]; }

// Does the arc run counterclockwise in the plane? Its parameter runs
// counterclockwise on the unit circle; the axes keep that sense or, with a
// negative determinant, reverse it.
bool counterclockwise(const ProfileEdge& arc) {
  return (arc.angle1 > arc.angle0) == (determinant(arc.axes) > 0.0);
}

bool wholeTurn(const ProfileEdge& arc) { return std::abs(arc.angle1 - arc.angle0) >= 2.0 * kPi; }

// The ellipse c + A·(cos θ, sin θ) as SVG names it: half-axes and the
// rotation of the first, from the singular value decomposition of A in
// closed form (J. Blinn, "Consider the lowly 2×2 matrix", IEEE Computer
// Graphics and Applications 16(2), 1996).
struct EllipseShape {
  double rx, ry, rotationDegrees;
};
EllipseShape ellipseOf(const dmat2& a) {
  // a = [[m00 m01] [m10 m11]] in rows: columns a[0], a[1] of glm.
  const double m00 = a[0][0], m10 = a[0][1], m01 = a[1][0], m11 = a[1][1];
  const double e = (m00 + m11) / 2, f = (m00 - m11) / 2;
  const double g = (m10 + m01) / 2, h = (m10 - m01) / 2;
  const double q = std::hypot(e, h), r = std::hypot(f, g);
  const double a1 = std::atan2(g, f), a2 = std::atan2(h, e);
  return {q + r, std::abs(q - r), degrees((a2 + a1) / 2)};
}

// ---- SVG ------------------------------------------------------------------------

// A point of the plane in SVG's frame, whose y axis points down.
std::string svgPoint(const dvec2& p) { return number(p.x) + " " + number(-p.y); }

void svgArc(std::string& d, const ProfileEdge& arc, double angle0, double angle1) {
  const EllipseShape shape = arc.circular()
                                 ? EllipseShape{std::hypot(arc.axes[0][0], arc.axes[0][1]),
                                                std::hypot(arc.axes[0][0], arc.axes[0][1]), 0.0}
                                 : ellipseOf(arc.axes);
  const bool large = std::abs(angle1 - angle0) > kPi;
  // SVG's sweep flag 1 runs its angle up in SVG's own coordinates (SVG
  // 1.1, 8.3.8 and F.6.5), whose y axis is the plane's mirrored: there a
  // counterclockwise arc of the plane runs its angle down, flag 0.
  const bool sweep = !counterclockwise(arc);
  d += " A " + number(shape.rx) + " " + number(shape.ry) + " " + number(-shape.rotationDegrees) +
       " " + (large ? "1" : "0") + " " + (sweep ? "1" : "0") + " " + svgPoint(arc.arcPoint(angle1));
}

// ---- DXF ------------------------------------------------------------------------

void group(std::string& out, int code, const std::string& value) {
  char text[8];
  std::snprintf(text, sizeof text, "%3d\n", code);
  out += text;
  out += value;
  out += "\n";
}

void dxfLine(std::string& out, const dvec2& a, const dvec2& b) {
  group(out, 0, "LINE");
  group(out, 8, "0");
  group(out, 10, number(a.x));
  group(out, 20, number(a.y));
  group(out, 30, "0");
  group(out, 11, number(b.x));
  group(out, 21, number(b.y));
  group(out, 31, "0");
}

void dxfArc(std::string& out, const ProfileEdge& arc, double tolerance) {
  if (!arc.circular()) {
    // R12 has no ellipse: chords within tolerance by the sagitta rule,
    // s = R (1 − cos(δ/2)) for a step δ on a circle of the largest radius R.
    const EllipseShape shape = ellipseOf(arc.axes);
    const double big = std::max(shape.rx, shape.ry);
    const double step = tolerance < big ? 2.0 * std::acos(1.0 - tolerance / big) : kPi / 2;
    const double sweep = arc.angle1 - arc.angle0;
    const int n = std::clamp(static_cast<int>(std::ceil(std::abs(sweep) / step)), 4, 1 << 20);
    dvec2 previous = arc.from;
    for (int i = 1; i <= n; ++i) {
      const dvec2 next = i == n ? arc.to : arc.arcPoint(arc.angle0 + sweep * i / n);
      dxfLine(out, previous, next);
      previous = next;
    }
    return;
  }
  const double radius = std::hypot(arc.axes[0][0], arc.axes[0][1]);
  group(out, 0, wholeTurn(arc) ? "CIRCLE" : "ARC");
  group(out, 8, "0");
  group(out, 10, number(arc.center.x));
  group(out, 20, number(arc.center.y));
  group(out, 30, "0");
  group(out, 40, number(radius));
  if (wholeTurn(arc)) return;
  // A DXF arc runs counterclockwise from its start angle to its end angle.
  const dvec2 a = arc.from - arc.center, b = arc.to - arc.center;
  double start = degrees(std::atan2(a.y, a.x)), end = degrees(std::atan2(b.y, b.x));
  if (!counterclockwise(arc)) std::swap(start, end);
  group(out, 50, number(start));
  group(out, 51, number(end));
}

}  // namespace

std::optional<OutlineFormat> outlineFormatFor(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".svg") return OutlineFormat::Svg;
  if (ext == ".dxf") return OutlineFormat::Dxf;
  return std::nullopt;
}

std::string svgOutline(const Profile& evaluated) {
  ProfileBounds box = evaluated.bounds();
  if (box.empty()) box.lo = box.hi = dvec2(0.0);
  const dvec2 size = box.hi - box.lo;
  std::string d;
  for (const ProfileLoop& loop : evaluated.loops) {
    if (loop.edges.empty()) continue;
    if (!d.empty()) d += " ";
    d += "M " + svgPoint(loop.edges.front().from);
    for (const ProfileEdge& e : loop.edges) {
      if (e.kind == ProfileEdge::Kind::Segment) {
        d += " L " + svgPoint(e.to);
      } else if (e.kind == ProfileEdge::Kind::Quadratic) {
        d += " Q " + svgPoint(e.control1) + " " + svgPoint(e.to);
      } else if (e.kind == ProfileEdge::Kind::Cubic) {
        d += " C " + svgPoint(e.control1) + " " + svgPoint(e.control2) + " " + svgPoint(e.to);
      } else if (wholeTurn(e)) {
        // An arc command cannot close a whole ellipse on itself: two halves.
        const double middle = e.angle0 + (e.angle1 > e.angle0 ? kPi : -kPi);
        svgArc(d, e, e.angle0, middle);
        svgArc(d, e, middle, e.angle0 + (e.angle1 > e.angle0 ? 2 * kPi : -2 * kPi));
      } else {
        svgArc(d, e, e.angle0, e.angle1);
      }
    }
    d += " Z";
  }
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + number(size.x) +
         "mm\" height=\"" + number(size.y) + "mm\" viewBox=\"" + number(box.lo.x) + " " +
         number(-box.hi.y) + " " + number(size.x) + " " + number(size.y) + "\">\n";
  svg +=
      "  <path fill=\"none\" fill-rule=\"evenodd\" stroke=\"#000000\" stroke-width=\"0.1\" d=\"" +
      d + "\"/>\n";
  svg += "</svg>\n";
  return svg;
}

std::string dxfOutline(const Profile& evaluated, double tolerance) {
  std::string out;
  group(out, 0, "SECTION");
  group(out, 2, "HEADER");
  group(out, 9, "$ACADVER");
  group(out, 1, "AC1009");  // R12
  group(out, 0, "ENDSEC");
  group(out, 0, "SECTION");
  group(out, 2, "ENTITIES");
  // R12 has no curves but lines and circular arcs: Bézier curves as
  // polygons.
  for (const ProfileLoop& loop : bezierEdgesFlattened(evaluated, tolerance).loops)
    for (const ProfileEdge& e : loop.edges) {
      if (e.kind == ProfileEdge::Kind::Segment)
        dxfLine(out, e.from, e.to);
      else
        dxfArc(out, e, tolerance);
    }
  group(out, 0, "ENDSEC");
  group(out, 0, "EOF");
  return out;
}

void writeOutlineFile(const std::string& path, const Profile& evaluated, double tolerance) {
  const std::optional<OutlineFormat> format = outlineFormatFor(path);
  if (!format)
    throw std::runtime_error("cannot write " + path + ": an outline is written as .svg or .dxf");
  const std::string text =
      *format == OutlineFormat::Svg ? svgOutline(evaluated) : dxfOutline(evaluated, tolerance);
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + path);
  }
  file.commit();
}

}  // namespace csgray::detail
