#include "meshio/mesh_writer.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/srgb.h"
#include "meshio/binary_stl_writer.h"
#include "meshio/lib3mf_handle.h"

namespace csgray::detail {

namespace {

// Points in doubles, so that text formats keep every digit.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OpenMeshMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void writeWithOpenMesh(const std::string& path, const std::string& tempPath, MeshFormat format,
                       const TriangleMesh& mesh, bool ascii) {
  OpenMeshMesh om;
  om.reserve(mesh.points.size(), mesh.size() * 3 / 2, mesh.size());
  std::vector<OpenMeshMesh::VertexHandle> vertices;
  vertices.reserve(mesh.points.size());
  for (const dvec3& p : mesh.points) vertices.push_back(om.add_vertex({p.x, p.y, p.z}));
  for (const TriangleMesh::Triangle& t : mesh.triangles)
    if (!om.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]).is_valid())
      throw std::runtime_error("cannot write " + path + ": the mesh is not a 2-manifold");
  om.request_face_normals();
  om.update_face_normals();

  OpenMesh::IO::Options options;
  const bool binary = (format == MeshFormat::Stl || format == MeshFormat::Ply) && !ascii;
  if (binary) options += OpenMesh::IO::Options::Binary;
  if (format == MeshFormat::Stl) options += OpenMesh::IO::Options::FaceNormal;
  if (format == MeshFormat::Ply && binary) options += OpenMesh::IO::Options::LSB;
  std::ofstream out(tempPath, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path + ": cannot create a file there");
  const char* ext = format == MeshFormat::Stl   ? ".stl"
                    : format == MeshFormat::Obj ? ".obj"
                    : format == MeshFormat::Off ? ".off"
                                                : ".ply";
  // 17 significant digits print every double so that it reads back the same.
  const bool written = OpenMesh::IO::write_mesh(om, out, ext, options, 17);
  out.close();  // its failure too: the last bytes are written then
  if (!written || !out)
    throw std::runtime_error("cannot write " + path + ": the writer failed (disk full?)");
}

// lib3mf 1.x reports errors as codes; a failed call throws with the
// library's own message where it has one.
void check3mf(LIB3MFRESULT result, const std::string& path, const char* what,
              NMR::PLib3MFBase* object = nullptr) {
  if (result == LIB3MF_OK) return;
  std::string message = "cannot write " + path + ": lib3mf could not " + what;
  DWORD code = 0;
  LPCSTR text = nullptr;
  if (object && NMR::lib3mf_getlasterror(object, &code, &text) == LIB3MF_OK && text)
    message += std::string(" (") + text + ")";
  throw std::runtime_error(message);
}

// lib3mf 1.8 prints a coordinate f as the integer part, cut toward zero,
// of f · 10⁶ taken in single precision, six digits after the point (so
// 63.98966 prints as 63.989664: the product is a float, and near 6.4·10⁷
// floats are 4 apart; seen on 900 000 random floats, every one printed
// so). Not every float can be written then: the exporter checks the mesh
// with each coordinate as the print of its float reads back
// (asSixDecimals), and the writer hands lib3mf a float that prints so.
// What a float handed to lib3mf reads back as:
double readBackOfPrint(float f) {
  const long long scaled = (long long)(f * 1000000.0f);
  char text[48];
  std::snprintf(text, sizeof text, "%s%lld.%06lld", scaled < 0 ? "-" : "",
                std::llabs(scaled) / 1000000, std::llabs(scaled) % 1000000);
  return double(std::strtof(text, nullptr));
}

// The float to hand to lib3mf for a coordinate the exporter rounded with
// asSixDecimals: the nearest one whose print reads back as it, within a
// few steps either way (the print is at most 5·10⁻⁶ from the float, two
// steps of a float below 128; the float itself should none do, as before).
float printsAsSixDecimals(double stored) {
  const float f = float(stored);
  float below = f, above = f;
  for (int step = 0; step <= 4; ++step) {
    if (readBackOfPrint(above) == stored) return above;
    if (readBackOfPrint(below) == stored) return below;
    above = std::nextafter(above, INFINITY);
    below = std::nextafter(below, -INFINITY);
  }
  return f;
}

// Where lib3mf writes a 3MF file: its callbacks (lib3mf 1.x,
// NMR_ExportStream_Callback.h) return 0 for success.
struct ZipBuffer {
  std::vector<char> bytes;
  std::size_t position = 0;
  static std::uint32_t write(std::uint8_t* data, std::uint32_t count, void* self) {
    auto& zip = *static_cast<ZipBuffer*>(self);
    if (zip.bytes.size() < zip.position + count) zip.bytes.resize(zip.position + count);
    std::copy(data, data + count, zip.bytes.begin() + std::ptrdiff_t(zip.position));
    zip.position += count;
    return 0;
  }
  static std::uint32_t seek(std::uint64_t position, void* self) {
    static_cast<ZipBuffer*>(self)->position = position;
    return 0;
  }
};

void write3mf(const std::string& path, const std::string& tempPath, const PartMesh& part) {
  using namespace NMR;
  Released model, materials, object, handler, defaults, item, writer;
  check3mf(lib3mf_createmodel(&model.object), path, "create a model");
  check3mf(lib3mf_model_setunit(model.object, MODELUNIT_MILLIMETER), path, "set the unit");

  // One base material per material of the part, coloured as the renderer
  // shows it: linear RGB encoded as sRGB (3MF colours are sRGB).
  check3mf(lib3mf_model_addbasematerialgroup(model.object, &materials.object), path,
           "add materials");
  DWORD groupId = 0;
  check3mf(lib3mf_resource_getresourceid(materials.object, &groupId), path, "name materials");
  std::vector<DWORD> materialIndex;
  const SrgbEncoder srgb;
  for (std::size_t i = 0; i < std::max<std::size_t>(1, part.materials.size()); ++i) {
    dvec3 c = Material{}.color;
    if (i < part.materials.size() && part.materials[i]) c = part.materials[i]->color;
    std::string name = "material " + std::to_string(i + 1);
    DWORD index = 0;
    check3mf(lib3mf_basematerial_addmaterialutf8(materials.object, name.c_str(), srgb(float(c.r)),
                                                 srgb(float(c.g)), srgb(float(c.b)), &index),
             path, "add a material");
    // lib3mf leaves the alpha of a colour added this way at 0 (clear).
    check3mf(lib3mf_basematerial_setdisplaycolorrgba(materials.object, index, srgb(float(c.r)),
                                                     srgb(float(c.g)), srgb(float(c.b)), 255),
             path, "colour a material");
    materialIndex.push_back(index);
  }

  check3mf(lib3mf_model_addmeshobject(model.object, &object.object), path, "add a mesh");
  check3mf(
      lib3mf_object_setnameutf8(object.object, std::filesystem::path(path).stem().string().c_str()),
      path, "name the mesh");
  std::vector<MODELMESHVERTEX> vertices(part.mesh.points.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      vertices[i].m_fPosition[k] = printsAsSixDecimals(part.mesh.points[i][k]);
  std::vector<MODELMESHTRIANGLE> triangles(part.mesh.size());
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) triangles[i].m_nIndices[k] = part.mesh.triangles[i][k];
  check3mf(lib3mf_meshobject_setgeometry(object.object, vertices.data(), DWORD(vertices.size()),
                                         triangles.data(), DWORD(triangles.size())),
           path, "set the mesh");
  check3mf(lib3mf_meshobject_createpropertyhandler(object.object, &handler.object), path,
           "colour the mesh");
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    std::uint32_t m = i < part.material.size() ? part.material[i] : 0;
    check3mf(lib3mf_propertyhandler_setbasematerial(
                 handler.object, DWORD(i), groupId,
                 materialIndex[std::min<std::size_t>(m, materialIndex.size() - 1)]),
             path, "colour a triangle");
  }
  // 3MF wants a default for an object whose triangles have properties.
  check3mf(lib3mf_object_createdefaultpropertyhandler(object.object, &defaults.object), path,
           "colour the mesh");
  check3mf(
      lib3mf_defaultpropertyhandler_setbasematerial(defaults.object, groupId, materialIndex[0]),
      path, "colour the mesh");
  check3mf(lib3mf_model_addbuilditem(model.object, object.object, nullptr, &item.object), path,
           "add the part to the build");

  check3mf(lib3mf_model_querywriter(model.object, "3mf", &writer.object), path, "make a writer");
  // lib3mf writes the zip into memory, and this code writes it to the
  // temporary: lib3mf's own file writer aborts the process (an exception
  // through a destructor) when the disk is full.
  ZipBuffer zip;
  check3mf(lib3mf_writer_writetocallback(writer.object, reinterpret_cast<void*>(&ZipBuffer::write),
                                         reinterpret_cast<void*>(&ZipBuffer::seek), &zip),
           path, "write the file", writer.object);
  std::ofstream out(tempPath, std::ios::binary | std::ios::trunc);
  out.write(zip.bytes.data(), std::streamsize(zip.bytes.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path + ": the write failed (disk full?)");
}

}  // namespace

MeshFormat meshFormatFor(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".3mf") return MeshFormat::ThreeMf;
  throw std::invalid_argument("cannot write " + path + ": unknown mesh format '" + ext +
                              "' (use .stl, .obj, .off, .ply or .3mf)");
}

namespace {

// Each stores a zero as +0: CGAL's interval arithmetic takes other steps
// where the compiler may use AVX, and a vertex its exact boolean puts on
// z = 0 came out −0 in the x86-64-v3 build and +0 in the portable one
// (−0 + 0 is +0 when rounding to nearest).
double asFloat(double x) { return double(float(x)) + 0.0; }
// OpenMesh prints a coordinate of an ASCII STL file as the float with ten
// significant digits.
double asTenDigits(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", double(float(x)));
  return std::strtod(text, nullptr) + 0.0;
}
// A coordinate as a 3MF file holds it (readBackOfPrint).
double asSixDecimals(double x) { return readBackOfPrint(float(x)) + 0.0; }

}  // namespace

// OpenMesh writes coordinates as floats in every format: binary STL as
// such, OBJ, OFF and PLY with every digit of the float, ASCII STL with ten
// significant digits.
StoredCoordinate storedCoordinate(MeshFormat format, bool ascii) {
  if (format == MeshFormat::ThreeMf) return asSixDecimals;
  return format == MeshFormat::Stl && ascii ? asTenDigits : asFloat;
}

void writeMeshFile(const std::string& path, const PartMesh& part, bool ascii) {
  // OpenMesh reports each write on its log stream; csgray prints its own line.
  omlog().disable();
  const MeshFormat format = meshFormatFor(path);
  AtomicFile file(path);
  if (format == MeshFormat::ThreeMf)
    write3mf(path, file.tempPath(), part);
  else if (format == MeshFormat::Stl && !ascii)
    writeBinaryStl(path, file.tempPath(), part.mesh);
  else
    writeWithOpenMesh(path, file.tempPath(), format, part.mesh, ascii);
  file.commit();
}

}  // namespace csgray::detail
