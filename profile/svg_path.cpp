#include "profile/svg_path.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/degrees.h"

namespace csgray::detail {

namespace {

using std::numbers::pi;

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The signed angle from u to v, in (−π, π].
double angleBetween(const dvec2& u, const dvec2& v) {
  return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
}

}  // namespace

std::size_t svgNumberEnd(std::string_view text, std::size_t at) {
  std::size_t i = at;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t digitsStart = i;
  while (i < text.size() && isDigit(text[i])) ++i;
  bool digits = i > digitsStart;
  if (i < text.size() && text[i] == '.') {
    const std::size_t fraction = ++i;
    while (i < text.size() && isDigit(text[i])) ++i;
    digits |= i > fraction;
  }
  if (!digits) return at;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    if (j < text.size() && isDigit(text[j])) {
      while (j < text.size() && isDigit(text[j])) ++j;
      i = j;
    }
  }
  return i;
}

std::optional<double> svgNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double v = 0.0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(v) || std::abs(v) > 1e15)
    return std::nullopt;
  return v;
}

std::string svgExcerpt(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 30))
    if (isSpace(c)) {
      if (out.empty() || out.back() != ' ') out += ' ';
    } else {
      // Another control byte as '?': a NUL would end the message there
      // (an exception's text is a C string), an escape would reach the
      // terminal.
      const auto byte = static_cast<unsigned char>(c);
      out += byte < 0x20 || byte == 0x7f ? '?' : c;
    }
  return text.size() > 30 ? out + "..." : out;
}

std::vector<double> parseSvgNumbers(std::string_view text) {
  std::vector<double> out;
  std::size_t at = 0;
  bool comma = false;
  while (true) {
    while (at < text.size() && (isSpace(text[at]) || (text[at] == ',' && !comma))) {
      comma |= text[at] == ',';
      ++at;
    }
    if (at >= text.size()) break;
    const std::size_t end = svgNumberEnd(text, at);
    if (end == at)
      throw std::invalid_argument("expected a number, found '" + svgExcerpt(text.substr(at)) + "'");
    const std::optional<double> v = svgNumber(text.substr(at, end - at));
    if (!v)
      throw std::invalid_argument("the number " + svgExcerpt(text.substr(at, end - at)) +
                                  " is out of range");
    out.push_back(*v);
    at = end;
    comma = false;
  }
  return out;
}

namespace {

class PathParser {
 public:
  explicit PathParser(std::string_view data) : data_(data) {}

  std::vector<SvgSubpath> parse() {
    skipSeparators();
    if (at_ < data_.size() && data_[at_] != 'M' && data_[at_] != 'm')
      fail("path data must start with a moveto (M or m)");
    char command = 0;
    while (true) {
      skipSeparators();
      if (at_ >= data_.size()) break;
      const char c = data_[at_];
      if (std::isalpha(static_cast<unsigned char>(c))) {
        if (std::string_view("MmLlHhVvCcSsQqTtAaZz").find(c) == std::string_view::npos)
          fail(std::string("'") + c + "' is not a path command");
        command = c;
        commandStart_ = at_;
        ++at_;
        if (c == 'Z' || c == 'z') {
          close();
          continue;
        }
      } else if (command == 0 || command == 'Z' || command == 'z') {
        fail("expected a command letter, found '" + std::string(1, c) + "'");
      }
      // Repeats after a moveto are linetos (SVG 1.1, 8.3.2).
      segment(command);
      if (command == 'M') command = 'L';
      if (command == 'm') command = 'l';
    }
    finishSubpath();
    return std::move(subpaths_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    const std::size_t from = commandStart_;
    // The data read since the last command.
    const std::string context = svgExcerpt(data_.substr(from, at_ - from));
    throw std::invalid_argument(context.empty() ? what : "after '" + context + "': " + what);
  }

  void skipSeparators() {
    while (at_ < data_.size() && isSpace(data_[at_])) ++at_;
    if (at_ < data_.size() && data_[at_] == ',') {
      ++at_;
      while (at_ < data_.size() && isSpace(data_[at_])) ++at_;
    }
  }

  double number() {
    skipSeparators();
    const std::size_t end = svgNumberEnd(data_, at_);
    if (end == at_) {
      if (at_ >= data_.size()) fail("expected a number, found the end of the data");
      fail("expected a number, found '" + std::string(1, data_[at_]) + "'");
    }
    const std::optional<double> v = svgNumber(data_.substr(at_, end - at_));
    if (!v) fail("the number " + svgExcerpt(data_.substr(at_, end - at_)) + " is out of range");
    at_ = end;
    return *v;
  }

  // An arc flag: one character, 0 or 1, which needs no separator after it.
  bool flag() {
    skipSeparators();
    if (at_ >= data_.size() || (data_[at_] != '0' && data_[at_] != '1'))
      fail("an arc flag must be 0 or 1");
    return data_[at_++] == '1';
  }

  dvec2 point(bool relative) {
    const double x = number();
    const double y = number();
    return relative ? current_ + dvec2(x, y) : dvec2(x, y);
  }

  void moveTo(const dvec2& p) {
    finishSubpath();
    current_ = start_ = p;
    started_ = true;
  }

  void add(const ProfileEdge& e) {
    if (!started_) {  // after a closepath: a new subpath from its start
      start_ = current_;
      started_ = true;
    }
    open_.edges.push_back(e);
    current_ = e.to;
  }

  void lineTo(const dvec2& p) {
    if (p != current_) add(ProfileEdge::segment(current_, p));
    current_ = p;
  }

  void close() {
    if (!open_.edges.empty()) {
      if (current_ != start_) open_.edges.push_back(ProfileEdge::segment(current_, start_));
      open_.edges.back().to = start_;
      open_.closed = true;
    }
    current_ = start_;
    finishSubpath();
    lastControl_.reset();
    lastKind_ = 0;
  }

  void finishSubpath() {
    if (!open_.edges.empty()) subpaths_.push_back(std::move(open_));
    open_ = {};
    started_ = false;
  }

  // The control point S and T imply: the reflection of the last curve's
  // (last) control point about the current point when the last segment was
  // a curve of the same degree, else the current point (SVG 1.1, 8.3.6
  // and 8.3.7).
  dvec2 smoothControl(char degreeKind) const {
    return lastKind_ == degreeKind && lastControl_ ? 2.0 * current_ - *lastControl_ : current_;
  }

  // One segment of the command's kind, its numbers read.
  void segment(char command) {
    const bool rel = std::islower(static_cast<unsigned char>(command));
    const char kind = char(std::toupper(static_cast<unsigned char>(command)));
    std::optional<dvec2> control;
    switch (kind) {
      case 'M':
        moveTo(point(rel));
        break;
      case 'L':
        lineTo(point(rel));
        break;
      case 'H': {
        const double x = number();
        lineTo({rel ? current_.x + x : x, current_.y});
        break;
      }
      case 'V': {
        const double y = number();
        lineTo({current_.x, rel ? current_.y + y : y});
        break;
      }
      case 'C':
      case 'S': {
        const dvec2 c1 = kind == 'C' ? point(rel) : smoothControl('C');
        const dvec2 c2 = point(rel);
        const dvec2 to = point(rel);
        if (c1 != current_ || c2 != current_ || to != current_)
          add(ProfileEdge::cubic(current_, c1, c2, to));
        current_ = to;
        control = c2;
        break;
      }
      case 'Q':
      case 'T': {
        const dvec2 c = kind == 'Q' ? point(rel) : smoothControl('Q');
        const dvec2 to = point(rel);
        if (c != current_ || to != current_) add(ProfileEdge::quadratic(current_, c, to));
        current_ = to;
        control = c;
        break;
      }
      case 'A': {
        const double rx = number(), ry = number(), rotation = number();
        const bool large = flag(), sweep = flag();
        const dvec2 to = point(rel);
        for (const ProfileEdge& e : svgArc(current_, rx, ry, rotation, large, sweep, to)) add(e);
        current_ = to;
        break;
      }
    }
    lastKind_ = kind == 'C' || kind == 'S' ? 'C' : kind == 'Q' || kind == 'T' ? 'Q' : 0;
    lastControl_ = control;
  }

  std::string_view data_;
  std::size_t at_ = 0, commandStart_ = 0;
  std::vector<SvgSubpath> subpaths_;
  SvgSubpath open_;
  dvec2 current_{0.0}, start_{0.0};
  bool started_ = false;
  char lastKind_ = 0;
  std::optional<dvec2> lastControl_;
};

}  // namespace

std::vector<ProfileEdge> svgArc(const dvec2& from, double rx, double ry, double rotationDegrees,
                                bool large, bool sweep, const dvec2& to) {
  if (from == to) return {};
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (rx == 0.0 || ry == 0.0) return {ProfileEdge::segment(from, to)};
  // F.6.5.1: the ends in the frame of the ellipse's axes, about their middle.
  const dvec2 turn = unitCircleDegrees(rotationDegrees);
  const double c = turn.x, s = turn.y;
  const dvec2 half = 0.5 * (from - to);
  const dvec2 p(c * half.x + s * half.y, -s * half.x + c * half.y);
  // F.6.6: radii too small to reach both ends grow until they just do.
  const double lambda = p.x * p.x / (rx * rx) + p.y * p.y / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  // F.6.5.2: the centre in that frame, on the side the flags choose.
  const double num = rx * rx * ry * ry - rx * rx * p.y * p.y - ry * ry * p.x * p.x;
  const double den = rx * rx * p.y * p.y + ry * ry * p.x * p.x;
  double k = std::sqrt(std::max(0.0, num / den));
  if (large == sweep) k = -k;
  const dvec2 centerLocal(k * rx * p.y / ry, -k * ry * p.x / rx);
  // F.6.5.3 and F.6.5.4: the centre, the start angle and the sweep.
  const dvec2 middle = 0.5 * (from + to);
  const dvec2 center(c * centerLocal.x - s * centerLocal.y + middle.x,
                     s * centerLocal.x + c * centerLocal.y + middle.y);
  const dvec2 u((p.x - centerLocal.x) / rx, (p.y - centerLocal.y) / ry);
  const dvec2 v((-p.x - centerLocal.x) / rx, (-p.y - centerLocal.y) / ry);
  const double theta = std::atan2(u.y, u.x);
  double delta = angleBetween(u, v);
  if (!sweep && delta > 0.0) delta -= 2.0 * pi;
  if (sweep && delta < 0.0) delta += 2.0 * pi;
  // Half circles: the angle between opposite vectors is ±π by rounding;
  // the flag decides.
  if (std::abs(std::abs(delta) - pi) < 1e-12) delta = sweep ? pi : -pi;
  const dmat2 axes(rx * c, rx * s, -ry * s, ry * c);  // columns: the turned axes
  ProfileEdge arc = ProfileEdge::arc(center, axes, theta, theta + delta);
  arc.from = from;
  arc.to = to;
  return {arc};
}

std::vector<SvgSubpath> parseSvgPath(std::string_view data) { return PathParser(data).parse(); }

}  // namespace csgray::detail
