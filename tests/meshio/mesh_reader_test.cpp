// Mesh files in: every format reads the same box to the same volume, every
// kind of bad file gets a one-line message naming the file and where, a
// mesh that is not a solid is refused naming the faces, repair=true fixes
// what it can and says so, and mesh{} in a script is a solid that takes
// part in booleans, with its file kept inside the script's folder.
#include "meshio/mesh_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/vec2.hpp>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "export/cgal/mesh_repair.h"
#include "export/cgal/mesh_validity.h"
#include "meshio/mesh_import.h"
#include "script/script.h"
#include "test_support.h"

namespace csgray::detail {
namespace {

namespace fs = std::filesystem;

const std::string kMeshes = CSGRAY_SOURCE_DIR "/tests/meshes/";
constexpr double kPi = std::numbers::pi;

std::string readError(const std::string& name) {
  try {
    readMeshFile(kMeshes + name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

std::string importError(const std::string& name, bool repair = false) {
  std::string report;
  try {
    importMesh(kMeshes + name, repair, report);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// ---- Good files ---------------------------------------------------------------

class BoxFile : public ::testing::TestWithParam<std::string> {};

// The box [0,2]×[0,3]×[0,4], written in every format and variant: 8 shared
// points, 12 triangles, volume 24, and a valid solid.
TEST_P(BoxFile, ReadsToTheSameSolid) {
  TriangleMesh mesh = readMeshFile(kMeshes + GetParam());
  EXPECT_EQ(mesh.points.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_DOUBLE_EQ(mesh.volume(), 24.0);
  EXPECT_DOUBLE_EQ(mesh.area(), 2 * (6.0 + 8.0 + 12.0));
  Bounds b = mesh.bounds();
  test::expectVecNear(b.lo, dvec3(0, 0, 0), 0.0);
  test::expectVecNear(b.hi, dvec3(2, 3, 4), 0.0);
  EXPECT_EQ(meshDefect(mesh).text, "");
}

INSTANTIATE_TEST_SUITE_P(Formats, BoxFile,
                         ::testing::Values("box_ascii.stl", "box_binary.stl",
                                           "box_solid_header.stl", "box.obj", "box.off",
                                           "box_ascii.ply", "box_le.ply", "box_be.ply"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// Non-convex faces are split by ear clipping, not by a fan that would
// cover the notch: an L-shaped prism, area 4 times height 5.
TEST(MeshReader, NonConvexFacesAreEarClipped) {
  TriangleMesh mesh = readMeshFile(kMeshes + "l_prism.obj");
  EXPECT_DOUBLE_EQ(mesh.volume(), 20.0);
  EXPECT_EQ(meshDefect(mesh).text, "");
}

// A face of many corners is ear clipped too: a star prism whose caps have
// 400 corners, 200 of them reflex (a fan would cross the notches), with the
// volume of its caps' area, n/2 · R·r · sin(2π/n), times the height.
TEST(MeshReader, LargeNonConvexFacesAreEarClipped) {
  const int n = 400;
  const double outer = 10.0, inner = 4.0, height = 5.0;
  std::string obj;
  for (double z : {0.0, height})
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * kPi * i / n, r = i % 2 ? inner : outer;
      obj += "v " + std::to_string(r * std::cos(a)) + " " + std::to_string(r * std::sin(a)) + " " +
             std::to_string(z) + "\n";
    }
  std::string bottom = "f", top = "f";
  for (int i = 0; i < n; ++i) {
    bottom += " " + std::to_string(n - i);
    top += " " + std::to_string(n + i + 1);
  }
  obj += bottom + "\n" + top + "\n";
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    obj += "f " + std::to_string(i + 1) + " " + std::to_string(j + 1) + " " +
           std::to_string(n + j + 1) + " " + std::to_string(n + i + 1) + "\n";
  }
  TriangleMesh mesh = readMesh(obj, "star.obj");
  EXPECT_EQ(mesh.triangles.size(), std::size_t(2 * (n - 2) + 2 * n));
  EXPECT_EQ(meshDefect(mesh).text, "");
  // The corners were written with six decimals: the volume of those points.
  auto corner = [&](int i) {
    const double a = 2.0 * kPi * (i % n) / n, r = i % 2 ? inner : outer;
    return glm::dvec2(std::stod(std::to_string(r * std::cos(a))),
                      std::stod(std::to_string(r * std::sin(a))));
  };
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec2 p = corner(i), q = corner(i + 1);
    area += 0.5 * (p.x * q.y - q.x * p.y);
  }
  EXPECT_NEAR(mesh.volume(), area * height, 1e-9);
  EXPECT_NEAR(mesh.volume(), n / 2.0 * outer * inner * std::sin(2.0 * kPi / n) * height, 1e-3);
}

TEST(MeshReader, TheFormatComesFromTheExtensionInAnyCase) {
  std::ifstream in(kMeshes + "box.off");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_DOUBLE_EQ(readMesh(text, "BOX.OFF").volume(), 24.0);
  EXPECT_THROW(readMesh(text, "box.3ds"), std::invalid_argument);
}

// ---- Bad files: one line naming the file and where -----------------------------

struct BadFile {
  const char* file;
  const char* message;  // the whole message, file and place included
};

class BadMeshFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadMeshFile, IsRefusedWithItsMessage) {
  std::string e = readError(GetParam().file);
  EXPECT_EQ(e, GetParam().message);
  EXPECT_EQ(e.find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, BadMeshFile,
    ::testing::Values(
        BadFile{"empty.stl", "empty.stl: the file is empty"},
        BadFile{"short.stl", "short.stl: truncated: 3 bytes, a binary STL has at least 84"},
        BadFile{"truncated_binary.stl",
                "truncated_binary.stl: binary STL declares 12 triangles, which take 684 bytes, "
                "but the file has 334 (truncated or wrong count)"},
        BadFile{"huge_count.stl",
                "huge_count.stl: binary STL declares 4294967295 triangles, which take "
                "214748364834 bytes, but the file has 134 (truncated or wrong count)"},
        BadFile{"solid_header_wrong_size.stl",
                "solid_header_wrong_size.stl: a binary STL whose header begins with \"solid\", "
                "declaring 12 triangles (684 bytes) in a file of 677 bytes"},
        BadFile{"truncated.3mf",
                "truncated.3mf: not a 3MF file lib3mf can read (Could not read ZIP file)"},
        BadFile{"truncated_ascii.stl",
                "truncated_ascii.stl:40: the file ends inside a facet (truncated?)"},
        BadFile{"no_endsolid.stl",
                "no_endsolid.stl:85: the file ends without endsolid (truncated?)"},
        BadFile{"nan.stl", "nan.stl:13: coordinate \"nan\" is not finite"},
        BadFile{"inf_binary.stl",
                "inf_binary.stl: triangle 2 (byte 228): coordinate inf is not finite"},
        BadFile{"two_vertex_facet.stl",
                "two_vertex_facet.stl:6: the facet has 2 vertices; STL facets have 3"},
        BadFile{"out_of_range.obj",
                "out_of_range.obj:19: face index 9 is out of range (8 vertices)"},
        BadFile{"index_zero.obj", "index_zero.obj:19: face index 0: OBJ counts vertices from 1"},
        BadFile{"negative_out_of_range.obj",
                "negative_out_of_range.obj:19: face index -9 is out of range (8 vertices so far)"},
        BadFile{"two_corner_face.obj",
                "two_corner_face.obj:19: a face needs at least 3 vertices, this one has 2"},
        BadFile{"bad_number.obj", "bad_number.obj:11: \"four\" is not a number"},
        // Ten vertices declared, eight given: face lines are read as
        // vertices, and the faces run out.
        BadFile{"wrong_count.off",
                "wrong_count.off:17: the file ends after 4 of 6 faces (truncated?)"},
        BadFile{"huge_count.off",
                "huge_count.off:3: declares 100000000 vertices, more than a file of this size "
                "holds"},
        BadFile{"out_of_range.off",
                "out_of_range.off:17: face index 8 is out of range (8 vertices)"},
        BadFile{"truncated_le.ply",
                "truncated_le.ply: byte 597: a list of 4 items is longer than the rest of the file "
                "(truncated?)"},
        BadFile{"huge_count.ply",
                "huge_count.ply: element vertex declares 4000000000 items, more than the rest "
                "of the file holds (truncated?)"},
        BadFile{"out_of_range_ascii.ply",
                "out_of_range_ascii.ply:29: face 5: vertex index 70 is out of range (8 vertices)"},
        // A whole number in full, not as 3e+09.
        BadFile{"huge_index_ascii.ply",
                "huge_index_ascii.ply:29: face 5: vertex index 3000000000 is out of range (8 "
                "vertices)"},
        BadFile{"inf_be.ply", "inf_be.ply: byte 499: vertex 7: coordinate inf is not finite"},
        BadFile{"no_faces.ply", "no_faces.ply: the file has no faces"}),
    [](const auto& info) {
      std::string name = info.param.file;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

TEST(MeshReader, AMissingFileIsNamed) {
  EXPECT_EQ(readError("missing.stl"), "missing.stl: no such file");
}

// Caps are checked before anything is read or allocated.
// The message of what f throws, or "(no error)".
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// A 3MF file's build: the box in a components object moved by 5 along x,
// placed turned 90° about z and moved by (10, 20, 30), and the box mirrored
// in x, whose faces the reader turns back outward (tests/meshes/generate.py).
TEST(MeshReader, ThreeMfBuildItemsAndComponentsArePlaced) {
  const TriangleMesh mesh = readMeshFile(kMeshes + "placed_components.3mf");
  EXPECT_EQ(mesh.size(), 24u);
  EXPECT_NEAR(mesh.volume(), 2 * 24.0, 1e-12);
  EXPECT_EQ(meshDefect(mesh).text, "");
  dvec3 lo(kInfinity), hi(-kInfinity);
  for (const dvec3& p : mesh.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  EXPECT_EQ(lo, dvec3(-2, 0, 0));
  EXPECT_EQ(hi, dvec3(10, 27, 34));
}

TEST(MeshReader, UpperCaseAsciiStlIsRead) {
  const std::string stl =
      "SOLID T\n"
      "FACET NORMAL 0 0 -1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 0 1 0\nVERTEX 1 0 "
      "0\nENDLOOP\nENDFACET\n"
      "FACET NORMAL 0 -1 0\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 0 "
      "1\nENDLOOP\nENDFACET\n"
      "FACET NORMAL -1 0 0\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 0 0 1\nVERTEX 0 1 "
      "0\nENDLOOP\nENDFACET\n"
      "FACET NORMAL 1 1 1\nOUTER LOOP\nVERTEX 1 0 0\nVERTEX 0 1 0\nVERTEX 0 0 "
      "1\nENDLOOP\nENDFACET\n"
      "ENDSOLID T\n";
  TriangleMesh mesh = readStl(stl, "upper.stl");
  EXPECT_EQ(mesh.size(), 4u);
  EXPECT_NEAR(mesh.volume(), 1.0 / 6.0, 1e-15);
}

TEST(MeshReader, OffWithMoreFacesThanDeclaredIsRefused) {
  const std::string off =
      "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(errorOf([&] { readOff(off, "extra.off"); }),
            "extra.off:10: more faces than the 3 the header declares");
}

TEST(MeshReader, AFractionalPlyIndexIsNamedSo) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1.5 2\n";
  const std::string e = errorOf([&] { readPly(ply, "frac.ply"); });
  EXPECT_NE(e.find("vertex index 1.5 is not a whole number"), std::string::npos) << e;
}

TEST(MeshReader, TheMostNegativeObjIndexIsOutOfRange) {
  // −INT64_MIN does not exist: the range test must not negate the index.
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -9223372036854775808 3 2\n";
  try {
    readObj(obj, "negative.obj");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "negative.obj:5: face index -9223372036854775808 is out of range (4 vertices so far)");
  }
}

// An OBJ vertex may carry a weight or a colour after x, y and z, and
// nothing else.
TEST(MeshReader, ObjVertexTakesNumbersAfterItsCoordinates) {
  const std::string faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string coloured = "v 0 0 0 0.5 0.2 0.1\nv 1 0 0 1\nv 0 1 0\nv 0 0 1\n" + faces;
  EXPECT_EQ(readObj(coloured, "coloured.obj").triangles.size(), 4u);
  const std::string word = "v 0 0 0\nv 1 0 0 extra\nv 0 1 0\nv 0 0 1\n" + faces;
  EXPECT_EQ(errorOf([&] { readObj(word, "word.obj"); }), "word.obj:2: \"extra\" is not a number");
}

// A face's corner is v, v/vt, v/vt/vn or v//vn; the texture and normal
// indices are not used, but a corner written otherwise is refused.
TEST(MeshReader, ObjCornersTakeOnlyTheFourForms) {
  const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const std::string good = points + "f 1 3/1 2/1/1\nf 1//1 2 4\nf 1 4 3\nf 2 3 4\n";
  EXPECT_EQ(readObj(good, "good.obj").triangles.size(), 4u);
  for (const std::string corner : {"1/", "1//", "1/x", "1/2/", "1//x", "1/2/3/4", "1/2x"}) {
    const std::string obj = points + "f " + corner + " 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
    EXPECT_EQ(
        errorOf([&] { readObj(obj, "corner.obj"); }),
        "corner.obj:5: \"" + corner + "\" is not a corner: OBJ writes v, v/vt, v/vt/vn or v//vn")
        << corner;
  }
}

// ---- Vertices that are not three finite numbers, in every text format ----------

// A tetrahedron in the text of a format, its second vertex written as
// `second`; the line of that vertex is secondVertexLine(format).
std::string tetrahedron(const std::string& format, const std::string& second) {
  const std::string v[4] = {"0 0 0", second, "0 1 0", "0 0 1"};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string text;
  if (format == "stl") {
    text = "solid t\n";
    for (const auto& f : faces) {
      text += "facet normal 0 0 0\nouter loop\n";
      for (int k : f) text += "vertex " + v[k] + "\n";
      text += "endloop\nendfacet\n";
    }
    return text + "endsolid t\n";
  }
  if (format == "ply")
    text =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  if (format == "off") text = "OFF\n4 4 0\n";
  for (const std::string& p : v) text += (format == "obj" ? "v " : "") + p + "\n";
  for (const auto& f : faces)
    text += format == "obj" ? "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) +
                                  " " + std::to_string(f[2] + 1) + "\n"
                            : "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
                                  std::to_string(f[2]) + "\n";
  return text;
}

// The line of the second vertex: in STL the first facet's last corner.
int secondVertexLine(const std::string& format) {
  return format == "stl" ? 6 : format == "obj" ? 2 : format == "off" ? 4 : 11;
}

std::string readTetrahedronError(const std::string& format, const std::string& second) {
  try {
    readMesh(tetrahedron(format, second), "t." + format);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MeshReader, TheTetrahedronIsRead) {
  for (const std::string format : {"stl", "obj", "off", "ply"})
    EXPECT_NEAR(readMesh(tetrahedron(format, "1 0 0"), "t." + format).volume(), 1.0 / 6.0, 1e-15)
        << format;
}

// NaN and infinities written as text, in any case, and numbers beyond the
// range of a double are refused at their line.
TEST(MeshReader, NonFiniteCoordinatesAreRefusedAtTheirLine) {
  for (const std::string format : {"stl", "obj", "off", "ply"}) {
    const std::string at = "t." + format + ":" + std::to_string(secondVertexLine(format)) + ": ";
    for (const std::string bad : {"nan", "NaN", "inf", "-inf", "Infinity", "1e999", "-1e400"}) {
      const std::string e = readTetrahedronError(format, "1 " + bad + " 0");
      EXPECT_EQ(e.rfind(at, 0), 0u) << format << " " << bad << ": " << e;
      EXPECT_TRUE(e.ends_with(" is not finite") || e.ends_with(" is beyond the range of a double"))
          << e;
    }
  }
  EXPECT_EQ(readTetrahedronError("stl", "1 NaN 0"), "t.stl:6: coordinate \"nan\" is not finite");
  EXPECT_EQ(readTetrahedronError("obj", "1 -inf 0"), "t.obj:2: coordinate \"-inf\" is not finite");
  EXPECT_EQ(readTetrahedronError("off", "1 1e999 0"),
            "t.off:4: coordinate \"1e999\" is beyond the range of a double");
  EXPECT_EQ(readTetrahedronError("ply", "1 nan 0"),
            "t.ply:11: vertex 1: coordinate nan is not finite");
}

// A vertex of two coordinates is refused at its own line: in PLY too, where
// it would otherwise take the next vertex's first value as its z.
TEST(MeshReader, TwoCoordinatesAreRefusedAtTheirLine) {
  EXPECT_EQ(readTetrahedronError("stl", "1 0"), "t.stl:6: a vertex needs x, y and z");
  EXPECT_EQ(readTetrahedronError("obj", "1 0"), "t.obj:2: a vertex needs x, y and z");
  EXPECT_EQ(readTetrahedronError("off", "1 0"), "t.off:4: a vertex needs x, y and z");
  EXPECT_EQ(readTetrahedronError("ply", "1 0"),
            "t.ply:11: vertex 1: the line ends before the values the header declares");
  // One value too many on a PLY line is a header that does not fit.
  EXPECT_EQ(readTetrahedronError("ply", "1 0 0 0"),
            "t.ply:11: vertex 1: the line has more values than the header declares");
  // Not even a number: the token is named.
  EXPECT_EQ(readTetrahedronError("obj", "1 0 z"), "t.obj:2: \"z\" is not a number");
  // STL's vertex has three numbers, no more (OBJ's may have a w and a
  // colour, OFF's a colour).
  EXPECT_EQ(readTetrahedronError("stl", "1 0 0 1"),
            "t.stl:6: a vertex has x, y and z only; this line has more (\"1\")");
}

// An ASCII STL with a stray NUL byte is refused at its line, as text: not
// taken for a binary file because its bytes hold a NUL.
TEST(MeshReader, AStrayNulInAnAsciiStlIsNamedAtItsLine) {
  const std::string e = readTetrahedronError("stl", std::string("1 0\0 0", 7));
  EXPECT_EQ(e.rfind("t.stl:6: ", 0), 0u) << e;
  EXPECT_EQ(e.find("binary"), std::string::npos) << e;
}

// Denormal coordinates are finite, and read.
TEST(MeshReader, DenormalCoordinatesAreRead) {
  for (const std::string format : {"stl", "obj", "off", "ply"})
    EXPECT_EQ(readTetrahedronError(format, "1 4.9e-324 0"), "(no error)") << format;
}

TEST(MeshReader, LimitsAreEnforced) {
  MeshReadLimits small;
  small.maxTriangles = 11;
  EXPECT_THROW(readMeshFile(kMeshes + "box.obj", small), std::invalid_argument);
  EXPECT_THROW(readMeshFile(kMeshes + "box_binary.stl", small), std::invalid_argument);
  small.maxTriangles = 12;
  EXPECT_EQ(readMeshFile(kMeshes + "box_binary.stl", small).size(), 12u);
  small.maxFileBytes = 100;
  try {
    readMeshFile(kMeshes + "box_binary.stl", small);
    ADD_FAILURE() << "read a file over the limit";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "box_binary.stl: the file is larger than the limit of 100 bytes");
  }
}

// Mangled copies of the good files (bytes flipped, cut short, repeated):
// each reads or is refused with a message, never anything else.
TEST(MeshReader, MangledFilesAreReadOrRefused) {
  std::mt19937_64 rng(5);
  for (const char* name : {"box_ascii.stl", "box_binary.stl", "box.obj", "box.off", "box_ascii.ply",
                           "box_le.ply", "box_be.ply"}) {
    std::ifstream in(kMeshes + name, std::ios::binary);
    const std::string original((std::istreambuf_iterator<char>(in)), {});
    for (int trial = 0; trial < 2000; ++trial) {
      std::string bytes = original;
      int edits = 1 + int(rng() % 4);
      for (int k = 0; k < edits; ++k) {
        std::size_t at = rng() % bytes.size();
        switch (rng() % 3) {
          case 0:
            bytes[at] = char(rng());
            break;
          case 1:
            bytes.resize(at);
            break;
          default:
            bytes.insert(at, bytes.substr(at, rng() % 16));
        }
        if (bytes.empty()) bytes = "x";
      }
      try {
        TriangleMesh mesh = readMesh(bytes, name);
        for (const auto& t : mesh.triangles)
          for (auto v : t) ASSERT_LT(v, mesh.points.size());
        meshDefect(mesh);
      } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()).rfind(name, 0), 0u) << e.what();
      }
    }
  }
}

// ---- Not solids ----------------------------------------------------------------

TEST(MeshValidity, OpenMeshesAreRefusedNamingTheEdge) {
  EXPECT_EQ(importError("open.obj"),
            "open.obj: open: the edge from vertex 1 (0, 0, 4) to vertex 2 (0, 3, 4) has one "
            "face (face 1); the mesh has a hole there");
}

TEST(MeshValidity, AFlippedFaceIsRefusedNamingItsNeighbour) {
  std::string e = importError("flipped_face.obj");
  EXPECT_EQ(e.rfind("flipped_face.obj: inconsistent orientation: faces ", 0), 0u) << e;
  EXPECT_NE(e.find("one of them is flipped"), std::string::npos) << e;
}

TEST(MeshValidity, AnInsideOutMeshIsRefused) {
  std::string e = importError("inside_out.off");
  EXPECT_EQ(e,
            "inside_out.off: inside out: the faces point inward (the mesh encloses a negative "
            "volume); faces must run counter-clockwise seen from outside (repair=true may fix "
            "this)");
}

TEST(MeshValidity, NonManifoldEdgesAndVerticesAreRefused) {
  // A repeated facet puts three faces on its edges.
  std::string e = importError("duplicated_facet.stl");
  EXPECT_EQ(e.rfind("duplicated_facet.stl: non-manifold: the edge from vertex ", 0), 0u) << e;
  EXPECT_NE(e.find("has 3 faces"), std::string::npos) << e;
  // Two boxes that share an edge: four faces there.
  e = importError("shared_edge.obj");
  EXPECT_EQ(e,
            "shared_edge.obj: non-manifold: the edge from vertex 5 (2, 3, 0) to vertex 6 (2, 3, "
            "4) has 4 faces (3, 7, 12, 16) (repair=true may fix this)");
  // Two tetrahedra tip to tip: every edge is fine, the shared vertex is not.
  TriangleMesh cones;
  cones.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  cones.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                     {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  EXPECT_EQ(meshDefect(cones).text,
            "non-manifold: vertex 0 (0, 0, 0) joins separate fans of faces (the surface touches "
            "itself at a point)");
}

TEST(MeshValidity, DegenerateFacesAreRefused) {
  std::string e = importError("degenerate_facet.stl");
  EXPECT_EQ(e,
            "degenerate_facet.stl: degenerate: face 12 uses a vertex twice (vertices 0, 0, 1) "
            "(repair=true may fix this)");
  TriangleMesh flat = readMeshFile(kMeshes + "box.off");
  flat.points.push_back({1, 0, 0});  // on the edge from (0,0,0) to (2,0,0)
  flat.triangles.push_back({0, 8, 4});
  EXPECT_EQ(meshDefect(flat).text,
            "degenerate: face 12 has no area: vertex 0 (0, 0, 0), vertex 8 (1, 0, 0) and vertex "
            "4 (2, 0, 0) are on one line");
}

TEST(MeshValidity, SelfIntersectionsAreRefusedNamingTheFaces) {
  std::string e = importError("overlapping.obj");
  EXPECT_EQ(e.rfind("overlapping.obj: self-intersecting: faces ", 0), 0u) << e;
  // The two faces named come one from each box (faces 0-11 and 12-23).
  int f = -1, g = -1;
  ASSERT_EQ(std::sscanf(e.c_str(), "overlapping.obj: self-intersecting: faces %d and %d", &f, &g),
            2);
  EXPECT_LT(f, 12);
  EXPECT_GE(g, 12);
  EXPECT_NE(e.find(" cross near ("), std::string::npos) << e;
  // Repairs do not resolve crossings: still refused.
  EXPECT_EQ(importError("overlapping.obj", true).rfind("overlapping.obj: self-intersecting", 0),
            0u);
}

TEST(MeshValidity, ACavityFacingInwardIsValid) {
  TriangleMesh outer = readMeshFile(kMeshes + "box.off");
  TriangleMesh cavity = outer;
  for (dvec3& p : cavity.points) p = dvec3(0.5) + p * 0.25;
  cavity.flip();
  outer.append(cavity);
  EXPECT_EQ(meshDefect(outer).text, "");
  EXPECT_DOUBLE_EQ(outer.volume(), 24.0 * (1 - 1.0 / 64));
  // Facing outward, the inner shell would be a second solid inside the
  // first: refused.
  cavity.flip();
  TriangleMesh doubled = readMeshFile(kMeshes + "box.off");
  doubled.append(cavity);
  EXPECT_EQ(meshDefect(doubled).text.rfind("inside out: the shell of face 12", 0), 0u)
      << meshDefect(doubled).text;
}

// ---- Repairs -------------------------------------------------------------------

TriangleMesh repaired(const std::string& name, const std::string& expectedReport) {
  std::string report;
  TriangleMesh mesh = importMesh(kMeshes + name, true, report);
  EXPECT_EQ(report, expectedReport) << name;
  EXPECT_EQ(meshDefect(mesh).text, "") << name;
  EXPECT_DOUBLE_EQ(mesh.volume(), 24.0) << name;
  return mesh;
}

TEST(MeshRepair, FixesAndReportsWhatItDid) {
  repaired("flipped_face.obj", "turned 2 faces to match their neighbours");
  repaired("duplicated_facet.stl", "removed 1 duplicated face");
  repaired("degenerate_facet.stl", "removed 1 face that uses a vertex twice");
  repaired("inside_out.off", "reversed 1 shell (12 faces)");
  // A good file needs nothing and says so by an empty report.
  repaired("box_binary.stl", "");
}

TEST(MeshRepair, MergesDuplicatedVertices) {
  // The box as a triangle soup: every triangle its own three points.
  TriangleMesh indexed = readMeshFile(kMeshes + "box.off"), soup;
  for (const auto& t : indexed.triangles) {
    auto n = std::uint32_t(soup.points.size());
    for (auto v : t) soup.points.push_back(indexed.points[v]);
    soup.triangles.push_back({n, n + 1, n + 2});
  }
  EXPECT_EQ(meshDefect(soup).kind, MeshDefect::Kind::Open);
  EXPECT_EQ(meshDefect(soup).text.rfind("open: ", 0), 0u);
  std::string report;
  TriangleMesh mesh = repairMesh(soup, report);
  EXPECT_EQ(report, "merged 28 duplicated vertices");
  EXPECT_EQ(mesh.points.size(), 8u);
  EXPECT_EQ(meshDefect(mesh).text, "");
  EXPECT_DOUBLE_EQ(mesh.volume(), 24.0);
}

TEST(MeshRepair, AnOpenMeshStaysRefused) {
  EXPECT_EQ(importError("open.obj", true).rfind("open.obj: open: ", 0), 0u);
}

TEST(MeshRepair, AMeshOfNothingButDegenerateFacesIsLeftEmpty) {
  // Four faces whose corners are one point: the repair removes them all,
  // and the empty mesh is not oriented (CGAL crashed on it).
  TriangleMesh point;
  for (int i = 0; i < 3; ++i) point.points.push_back(dvec3(1.0));
  for (int i = 0; i < 4; ++i) point.triangles.push_back({0, 1, 2});
  std::string report;
  const TriangleMesh mesh = repairMesh(point, report);
  EXPECT_TRUE(mesh.empty());
  EXPECT_EQ(report.rfind("merged 2 duplicated vertices", 0), 0u) << report;
  EXPECT_EQ(meshDefect(mesh).kind, MeshDefect::Kind::Empty) << meshDefect(mesh).text;
}

// ---- mesh{} in a script --------------------------------------------------------

class MeshScript : public ::testing::Test {
 protected:
  void SetUp() override {
    options_.folder = kMeshes;
    options_.loadMesh = importMesh;
    options_.warn = [this](const std::string& m) { warnings_.push_back(m); };
  }
  std::string errorOf(const std::string& source) { return test::scriptError(source, options_); }
  ScriptOptions options_;
  std::vector<std::string> warnings_;
};

// A box with the mesh box subtracted: the mesh takes part in the boolean,
// seen both by spans along rays and by point membership.
TEST_F(MeshScript, AMeshSubtractedFromABoxLeavesTheRest) {
  Scene scene = runScript(
      "return box{size={4, 4, 6}, center=true}:translate{1, 1.5, 2} - mesh{file=\"box.obj\"}",
      "part.lua", options_);
  ASSERT_EQ(scene.objects.size(), 1u);
  const Solid& solid = *scene.objects[0];
  EXPECT_FALSE(solid.contains({1, 1.5, 2}));
  EXPECT_TRUE(solid.contains({-0.5, 1.5, 2}));
  EXPECT_TRUE(solid.contains({1, 1.5, 4.5}));
  const Bounds box{dvec3(-1, -0.5, -1), dvec3(3, 3.5, 5)};
  EXPECT_NEAR(test::gridVolume(solid, box, 64), 96.0 - 24.0, 1e-9);
  test::expectSpansAgreeWithContainsOnRandomLines(solid);
  EXPECT_TRUE(warnings_.empty());
}

TEST_F(MeshScript, EveryFormatIsTheSameSolid) {
  for (const char* file : {"box_ascii.stl", "box_binary.stl", "box.off", "box_le.ply"}) {
    Scene scene =
        runScript(std::string("return mesh{file=\"") + file + "\"}", "part.lua", options_);
    EXPECT_NEAR(test::gridVolume(*scene.objects[0], {dvec3(0), dvec3(2, 3, 4)}, 32), 24.0, 1e-9)
        << file;
  }
}

TEST_F(MeshScript, RepairReportsGoToTheWarnings) {
  runScript("return mesh{file=\"inside_out.off\", repair=true}", "part.lua", options_);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_EQ(warnings_[0], "part.lua:1: mesh: inside_out.off: reversed 1 shell (12 faces)");
}

TEST_F(MeshScript, BadFilesStopTheScriptNamingTheFile) {
  EXPECT_EQ(errorOf("return mesh{file=\"out_of_range.obj\"}"),
            "part.lua:1: mesh: out_of_range.obj:19: face index 9 is out of range (8 vertices)");
  EXPECT_EQ(
      errorOf("return mesh{file=\"open.obj\"}").rfind("part.lua:1: mesh: open.obj: open: ", 0), 0u);
  EXPECT_EQ(errorOf("return mesh{}"),
            "part.lua:1: mesh: needs file=\"part.stl\" (STL, OBJ, OFF or PLY)");
  // A misspelt parameter is named, not ignored.
  std::string e = errorOf("return mesh{file=\"box.obj\", repiar=true}");
  EXPECT_EQ(e.rfind("part.lua:1: mesh: ", 0), 0u) << e;
  EXPECT_NE(e.find("repiar"), std::string::npos) << e;
}

TEST_F(MeshScript, WithoutALoaderMeshIsAnError) {
  options_.loadMesh = nullptr;
  EXPECT_EQ(errorOf("return mesh{file=\"box.obj\"}"),
            "part.lua:1: mesh: this program cannot read mesh files");
}

// Files come from the script's folder, or from folders allowed with
// --allow-path, by a relative or an absolute path.
TEST_F(MeshScript, FilesOutsideTheFolderNeedAllowPath) {
  const fs::path folder = fs::temp_directory_path() / "csgray_mesh_reader_test";
  fs::create_directories(folder / "script");
  fs::copy_file(kMeshes + "box.off", folder / "box.off", fs::copy_options::overwrite_existing);
  options_.folder = (folder / "script").string();
  const std::string absolute = (folder / "box.off").string();
  for (const std::string& name : {std::string("../box.off"), absolute}) {
    const std::string source = "return mesh{file=\"" + name + "\"}";
    EXPECT_EQ(errorOf(source), "part.lua:1: mesh: file " + name +
                                   " is outside the script's folder; give a path relative to it, "
                                   "or allow its folder with --allow-path");
  }
  options_.allowedFolders = {folder.string()};
  for (const std::string& name : {std::string("../box.off"), absolute})
    EXPECT_NO_THROW(runScript("return mesh{file=\"" + name + "\"}", "part.lua", options_)) << name;
  // An allowed folder does not open the rest of the file system.
  EXPECT_EQ(errorOf("return mesh{file=\"../../box.off\"}"),
            "part.lua:1: mesh: file ../../box.off is outside the script's folder; give a path "
            "relative to it or inside a folder given with --allow-path");
  fs::remove_all(folder);
}

}  // namespace
}  // namespace csgray::detail
