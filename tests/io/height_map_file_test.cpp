// Height maps (OpenSCAD's surface()): the heights of text files and PNG
// images as OpenSCAD reads them, and the closed solid over them, whose
// volume is each cell's mean height above the base.
#include "io/height_map_file.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "io/image_file.h"
#include "primitives/mesh_solid.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

const std::string kData = CSGRAY_SOURCE_DIR "/tests/data/openscad/";

double volumeOf(const SolidPtr& solid) {
  auto mesh = std::dynamic_pointer_cast<const MeshSolid>(solid);
  EXPECT_TRUE(mesh);
  return mesh ? mesh->volume() : 0.0;
}

std::string error(const std::string& text) {
  try {
    heightMapSolid(heightMapOfText(text, "map.dat"), false);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(HeightMap, TextRowsCommentsAndShortRows) {
  const HeightMap map = heightMapOfText("# a comment\n1 2\t3\n\n  # another\n4 5\r\n", "map.dat");
  ASSERT_EQ(map.rows, 2u);
  ASSERT_EQ(map.columns, 3u);
  EXPECT_EQ(map.at(0, 2), 3.0);
  EXPECT_EQ(map.at(1, 1), 5.0);
  EXPECT_EQ(map.at(1, 2), 0.0);  // filled up, as OpenSCAD does
  EXPECT_EQ(error("1 2\n3 4\n5 six\n"), "map.dat:3: 'six' is not a number");
  std::string nul = "1 2\n3";
  nul += '\0';
  nul += "4";  // a NUL byte inside a number: shown, not the end of the message
  EXPECT_EQ(error(nul), "map.dat:2: '3?4' is not a number");
  EXPECT_EQ(error("1 2 3\n"),
            "a height map needs at least 2 rows and 2 columns of heights, got 1 × 3");
}

TEST(HeightMap, VolumeIsEachCellsMeanAboveTheBase) {
  // Heights from −3 to 5: the base is one below the lowest, at −4; a
  // cell's four triangles over its middle point enclose its mean height.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(-3.0, 5.0);
  HeightMap map;
  map.rows = 6;
  map.columns = 9;
  for (std::size_t i = 0; i < map.rows * map.columns; ++i) map.heights.push_back(height(random));
  map.heights[0] = -3.0;
  double volume = 0.0;
  for (std::size_t r = 1; r < map.rows; ++r)
    for (std::size_t c = 1; c < map.columns; ++c)
      volume +=
          (map.at(r - 1, c - 1) + map.at(r - 1, c) + map.at(r, c - 1) + map.at(r, c)) / 4.0 + 4.0;
  const SolidPtr solid = heightMapSolid(map, true);
  EXPECT_NEAR(volumeOf(solid), volume, 1e-9 * volume);
  test::expectVecNear(solid->bounds().lo, {-4.0, -2.5, -4.0}, 1e-12);
  // Heights all above 1 stand on z = 0.
  map.heights.assign(map.heights.size(), 2.0);
  const SolidPtr raised = heightMapSolid(map, false);
  EXPECT_NEAR(volumeOf(raised), 2.0 * 8.0 * 5.0, 1e-9);
  test::expectVecNear(raised->bounds().lo, {0.0, 0.0, 0.0}, 1e-12);
}

TEST(HeightMap, PngGreyLevelsAsOpenScadReadsThem) {
  // OpenSCAD 2021.01's STL export of surface(file = "surface_image.png",
  // center = true) and of (center = false, invert = true), summed over its
  // triangles.
  const HeightMap map =
      readHeightMap(kData + "surface_image.png", "surface_image.png", false, readTextureImage);
  ASSERT_EQ(map.rows, 50u);
  ASSERT_EQ(map.columns, 50u);
  EXPECT_NEAR(volumeOf(heightMapSolid(map, true)), 87367.557376, 1e-5 * 87367.557376);
  const HeightMap inverted =
      readHeightMap(kData + "surface_image.png", "surface_image.png", true, readTextureImage);
  EXPECT_NEAR(volumeOf(heightMapSolid(inverted, false)), 157534.820722, 1e-5 * 157534.820722);
  // A text file is text whatever its name.
  EXPECT_EQ(readHeightMap(kData + "example010.dat", "example010.dat", false, nullptr).rows, 46u);
}

}  // namespace
}  // namespace csgray::detail
