// The outlines of regions as SVG and DXF, read back: the SVG path encloses
// the region's analytic area (lines and arcs by Green's theorem), and the
// DXF entities are the region's segments and circular arcs, joined end to
// end.
#include "meshio/outline_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "profile/region_evaluation.h"
#include "profile/shapes.h"
#include "profile/svg_reader.h"

namespace csgray::detail {
namespace {

constexpr double kPi = std::numbers::pi;

std::string attribute(const std::string& text, const std::string& name) {
  const std::size_t at = text.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const std::size_t begin = at + name.size() + 3;
  return text.substr(begin, text.find('"', begin) - begin);
}

// The area a path of M, L, A (circular) and Z commands encloses, in the
// plane's frame (SVG's y negated back), counterclockwise positive.
// Green's theorem: a segment p → q adds (p × q) / 2; an arc adds its chord's
// share and the circular segment between chord and arc, r²(φ − sin φ)/2
// for the arc's central angle φ, with the sign of its sense.
double pathArea(const std::string& d) {
  std::istringstream in(d);
  std::string command;
  dvec2 start(0.0), at(0.0);
  double twice = 0.0;
  auto point = [&] {
    double x, y;
    in >> x >> y;
    return dvec2(x, -y);
  };
  auto chord = [&](const dvec2& p, const dvec2& q) { twice += p.x * q.y - q.x * p.y; };
  while (in >> command) {
    if (command == "M") {
      start = at = point();
    } else if (command == "L") {
      const dvec2 q = point();
      chord(at, q);
      at = q;
    } else if (command == "A") {
      double rx, ry, rotation;
      int large, sweep;
      in >> rx >> ry >> rotation >> large >> sweep;
      EXPECT_DOUBLE_EQ(rx, ry) << "only circular arcs here";
      const dvec2 q = point();
      chord(at, q);
      double phi = 2.0 * std::asin(std::min(1.0, glm::length(q - at) / (2.0 * rx)));
      if (large) phi = 2.0 * kPi - phi;
      // Sweep flag 1 runs the angle up in SVG's coordinates (SVG 1.1,
      // F.6.5), whose y is the plane's mirrored: clockwise in the plane.
      twice += (sweep ? -1.0 : 1.0) * rx * rx * (phi - std::sin(phi));
      at = q;
    } else if (command == "Z") {
      chord(at, start);
      at = start;
    } else {
      ADD_FAILURE() << "unexpected command " << command;
      return 0.0;
    }
  }
  return twice / 2.0;
}

Profile evaluated(const RegionPtr& region) { return evaluate(*region, 1e-9); }

TEST(OutlineWriter, SvgEnclosesTheAnalyticArea) {
  struct Case {
    RegionPtr region;
    double area;
  } cases[] = {
      {circleRegion(2.0, std::nullopt), 4 * kPi},
      {Region::boolean(Region::Op::Difference,
                       {rectangleRegion("square", 4, 4, false),
                        circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {2, 2}})}),
       16 - kPi},
      // A stadium: a 4 × 2 rectangle with half discs at its ends.
      {Region::boolean(Region::Op::Union,
                       {rectangleRegion("rectangle", 4, 2, true),
                        circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {2, 0}}),
                        circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {-2, 0}})}),
       8 + kPi},
  };
  for (const Case& c : cases) {
    const std::string svg = svgOutline(evaluated(c.region));
    const std::string d = attribute(svg, "d");
    ASSERT_FALSE(d.empty()) << svg;
    EXPECT_NEAR(pathArea(d), c.area, 1e-9) << svg;
    EXPECT_EQ(attribute(svg, "fill-rule"), "evenodd");
  }
  // Its size in millimetres and its view box, y mirrored.
  const std::string svg = svgOutline(evaluated(rectangleRegion("rectangle", 4, 2, false)));
  EXPECT_EQ(attribute(svg, "width"), "4mm");
  EXPECT_EQ(attribute(svg, "height"), "2mm");
  EXPECT_EQ(attribute(svg, "viewBox"), "0 -2 4 2");
}

// The SVG read back (profile/svg_reader) is the region again: the same
// area, its box moved to the page's bottom left corner at the origin.
TEST(OutlineWriter, SvgReadsBackAsTheRegion) {
  const RegionPtr plate =
      Region::boolean(Region::Op::Difference,
                      {rectangleRegion("rectangle", 30, 20, true),
                       circleRegion(4.0, std::nullopt)->transformed({dmat2(1.0), {-8, 0}}),
                       rectangleRegion("square", 6, 6, true)->transformed({dmat2(1.0), {8, 0}})});
  const RegionPtr stadium = Region::boolean(
      Region::Op::Union, {rectangleRegion("rectangle", 4, 2, true),
                          circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {2, 0}}),
                          circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {-2, 0}})});
  const struct {
    RegionPtr region;
    double area;
  } cases[] = {{plate, 600 - 16 * kPi - 36}, {stadium, 8 + kPi}};
  for (const auto& c : cases) {
    const Profile written = evaluated(c.region);
    const RegionPtr read = readSvg(svgOutline(written), "outline.svg", {});
    const Profile again = evaluated(read);
    EXPECT_NEAR(area(again), c.area, 1e-9);
    const ProfileBounds box = written.bounds(), readBox = again.bounds();
    EXPECT_NEAR(readBox.lo.x, 0.0, 1e-12);
    EXPECT_NEAR(readBox.lo.y, 0.0, 1e-12);
    EXPECT_NEAR(readBox.hi.x, box.hi.x - box.lo.x, 1e-12);
    EXPECT_NEAR(readBox.hi.y, box.hi.y - box.lo.y, 1e-12);
  }
}

TEST(OutlineWriter, SvgArcsKeepTheirSense) {
  // A whole circle run clockwise, by a mirrored parameter or by a falling
  // angle, encloses −π; quarter discs count as they turn.
  Profile clockwise, counter;
  clockwise.loops.push_back({{ProfileEdge::arc(dvec2(0.0), dmat2(1, 0, 0, -1), 0, 2 * kPi)}});
  counter.loops.push_back({{ProfileEdge::arc(dvec2(0.0), dmat2(1.0), 2 * kPi, 0)}});
  EXPECT_NEAR(pathArea(attribute(svgOutline(clockwise), "d")), -kPi, 1e-12);
  EXPECT_NEAR(pathArea(attribute(svgOutline(counter), "d")), -kPi, 1e-12);
  Profile quarter;
  quarter.loops.push_back(
      {{ProfileEdge::segment({0, 0}, {2, 0}), ProfileEdge::arc(dvec2(0.0), dmat2(2.0), 0, kPi / 2),
        ProfileEdge::segment({0, 2}, {0, 0})}});
  EXPECT_NEAR(pathArea(attribute(svgOutline(quarter), "d")), kPi, 1e-12);
  // The three quarters left over: a large arc.
  Profile rest;
  rest.loops.push_back({{ProfileEdge::segment({0, 0}, {0, 2}),
                         ProfileEdge::arc(dvec2(0.0), dmat2(2.0), kPi / 2, 2 * kPi),
                         ProfileEdge::segment({2, 0}, {0, 0})}});
  EXPECT_NEAR(pathArea(attribute(svgOutline(rest), "d")), 3 * kPi, 1e-12);
}

// DXF's (group code, value) pairs, by entity.
struct Entity {
  std::string type;
  std::map<int, double> values;
};
std::vector<Entity> dxfEntities(const std::string& text) {
  std::istringstream in(text);
  std::string codeLine, value;
  std::vector<Entity> entities;
  bool inEntities = false;
  while (std::getline(in, codeLine) && std::getline(in, value)) {
    const int code = std::stoi(codeLine);
    if (code == 2 && value == "ENTITIES") inEntities = true;
    if (!inEntities) continue;
    if (code == 0) {
      if (value == "ENDSEC") break;
      entities.push_back({value, {}});
    } else if (!entities.empty() && code != 8) {
      entities.back().values[code] = std::stod(value);
    }
  }
  EXPECT_EQ(text.substr(text.size() - 8), "  0\nEOF\n");
  return entities;
}

TEST(OutlineWriter, DxfHoldsLinesAndArcs) {
  const RegionPtr stadium = Region::boolean(
      Region::Op::Union, {rectangleRegion("rectangle", 4, 2, true),
                          circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {2, 0}}),
                          circleRegion(1.0, std::nullopt)->transformed({dmat2(1.0), {-2, 0}})});
  const std::string text = dxfOutline(evaluated(stadium), 1e-3);
  EXPECT_NE(text.find("$ACADVER\n  1\nAC1009"), std::string::npos);
  double lineLength = 0.0, arcDegrees = 0.0;
  std::map<std::pair<double, double>, int> ends;  // each end of the outline twice
  auto end = [&](double x, double y) {
    ends[{std::round(x * 1e9) / 1e9, std::round(y * 1e9) / 1e9}]++;
  };
  for (const Entity& e : dxfEntities(text)) {
    if (e.type == "LINE") {
      lineLength +=
          std::hypot(e.values.at(11) - e.values.at(10), e.values.at(21) - e.values.at(20));
      end(e.values.at(10), e.values.at(20));
      end(e.values.at(11), e.values.at(21));
    } else {
      ASSERT_EQ(e.type, "ARC");
      EXPECT_DOUBLE_EQ(e.values.at(40), 1.0);
      EXPECT_DOUBLE_EQ(std::abs(e.values.at(10)), 2.0);
      const double cx = e.values.at(10), start = e.values.at(50), stop = e.values.at(51);
      double sweep = std::fmod(stop - start + 720.0, 360.0);
      arcDegrees += sweep;
      // The right end's arcs lie right of x = 2, the left's left of -2.
      const double mid = (start + sweep / 2) * kPi / 180;
      EXPECT_GT(cx * std::cos(mid), 0.0);
      end(cx + std::cos(start * kPi / 180), std::sin(start * kPi / 180));
      end(cx + std::cos(stop * kPi / 180), std::sin(stop * kPi / 180));
    }
  }
  EXPECT_NEAR(lineLength, 8.0, 1e-9);
  EXPECT_NEAR(arcDegrees, 360.0, 1e-9);
  for (const auto& [point, count] : ends)
    EXPECT_EQ(count, 2) << point.first << ", " << point.second;
  // A whole circle is a CIRCLE.
  const std::vector<Entity> circle =
      dxfEntities(dxfOutline(evaluated(circleRegion(3.0, {})), 1e-3));
  ASSERT_EQ(circle.size(), 1u);
  EXPECT_EQ(circle[0].type, "CIRCLE");
  EXPECT_DOUBLE_EQ(circle[0].values.at(40), 3.0);
}

TEST(OutlineWriter, DxfTurnsEllipsesIntoLinesWithinTheTolerance) {
  Profile ellipse;
  ellipse.loops.push_back({{ProfileEdge::arc(dvec2(0.0), dmat2(3, 0, 0, 1), 0, 2 * kPi)}});
  const std::vector<Entity> lines = dxfEntities(dxfOutline(ellipse, 1e-3));
  ASSERT_GT(lines.size(), 20u);
  for (const Entity& e : lines) {
    ASSERT_EQ(e.type, "LINE");
    // Both ends on the ellipse, the middle within the tolerance inside it.
    const double x = e.values.at(10), y = e.values.at(20);
    EXPECT_NEAR(x * x / 9 + y * y, 1.0, 1e-12);
    const double mx = (x + e.values.at(11)) / 2, my = (y + e.values.at(21)) / 2;
    EXPECT_LT(1.0 - std::sqrt(mx * mx / 9 + my * my), 3e-3);
  }
}

TEST(OutlineWriter, FilesByExtension) {
  EXPECT_EQ(outlineFormatFor("part.SVG"), OutlineFormat::Svg);
  EXPECT_EQ(outlineFormatFor("a/b.dxf"), OutlineFormat::Dxf);
  EXPECT_EQ(outlineFormatFor("part.stl"), std::nullopt);
  const auto path = std::filesystem::temp_directory_path() / "csgray_outline_writer_test.svg";
  writeOutlineFile(path.string(), evaluated(circleRegion(1.0, {})), 1e-3);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NEAR(pathArea(attribute(text.str(), "d")), kPi, 1e-12);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace csgray::detail
