// exportMesh(), the mesh files and meshDefect(): the exporter and the mesh
// files of the csgray command (export/cgal/mesh_boolean.h,
// meshio/mesh_writer.h, mesh_reader.h, export/cgal/mesh_validity.h).
#include "csgray/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>

#include "api/access.h"
#include "api/convert.h"
#include "api/errors.h"
#include "engine/cancellation.h"
#include "export/cgal/mesh_boolean.h"
#include "export/cgal/mesh_validity.h"
#include "export/printed_part.h"
#include "io/atomic_file.h"
#include "meshio/mesh_reader.h"
#include "meshio/mesh_writer.h"

namespace csgray {

using detail::toDetail;
using detail::toPublic;

namespace {

detail::MeshFormat formatOf(MeshFormat format) {
  switch (format) {
    case MeshFormat::Stl:
      return detail::MeshFormat::Stl;
    case MeshFormat::Obj:
      return detail::MeshFormat::Obj;
    case MeshFormat::Off:
      return detail::MeshFormat::Off;
    case MeshFormat::Ply:
      return detail::MeshFormat::Ply;
    case MeshFormat::ThreeMf:
      return detail::MeshFormat::ThreeMf;
  }
  return detail::MeshFormat::Stl;
}

// The points and triangles, refusing an index past the points.
detail::TriangleMesh triangleMesh(const Mesh& mesh) {
  detail::TriangleMesh made;
  made.points.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) made.points.push_back(toDetail(p));
  made.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
  return made;
}

void checkIndices(const Mesh& mesh) {
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= mesh.vertices.size())
        throw Error(ErrorCode::InvalidArgument, "mesh: a triangle names vertex " +
                                                    std::to_string(v) + " of " +
                                                    std::to_string(mesh.vertices.size()));
  if (!mesh.triangleMaterial.empty() && mesh.triangleMaterial.size() != mesh.triangles.size())
    throw Error(ErrorCode::InvalidArgument,
                "mesh: triangleMaterial must be empty or have one entry per triangle");
  for (std::uint32_t m : mesh.triangleMaterial)
    if (m >= mesh.materials.size())
      throw Error(ErrorCode::InvalidArgument, "mesh: a triangle names material " +
                                                  std::to_string(m) + " of " +
                                                  std::to_string(mesh.materials.size()));
}

// Far from the origin a 32-bit float (every mesh format stores floats, or
// fewer digits) cannot hold the tolerance: half its spacing at |x| is
// |x|·2⁻²⁴. As `csgray export` refuses it.
void checkPrecision(const detail::Solid& solid, double tolerance) {
  if (std::string problem = detail::floatPrecisionProblem(solid, tolerance); !problem.empty())
    throw Error(ErrorCode::NotPrintable, problem);
}

MeshDefect::Kind kindOf(detail::MeshDefect::Kind kind) {
  using K = detail::MeshDefect::Kind;
  switch (kind) {
    case K::None:
      return MeshDefect::Kind::None;
    case K::Empty:
      return MeshDefect::Kind::Empty;
    case K::NotFinite:
      return MeshDefect::Kind::NotFinite;
    case K::BadIndex:
      return MeshDefect::Kind::BadIndex;
    case K::Degenerate:
      return MeshDefect::Kind::Degenerate;
    case K::Open:
      return MeshDefect::Kind::Open;
    case K::NonManifold:
      return MeshDefect::Kind::NonManifold;
    case K::InconsistentOrientation:
      return MeshDefect::Kind::InconsistentOrientation;
    case K::SelfIntersecting:
      return MeshDefect::Kind::SelfIntersecting;
    case K::InsideOut:
      return MeshDefect::Kind::InsideOut;
  }
  return MeshDefect::Kind::None;
}

}  // namespace

double Mesh::volume() const {
  checkIndices(*this);
  return triangleMesh(*this).volume();
}

Mesh exportMesh(const Solid& solid, const ExportOptions& options) {
  if (!(options.tolerance >= 1e-6 && options.tolerance <= 1e3))
    throw Error(ErrorCode::InvalidArgument,
                "exportMesh: tolerance must be a number from 1e-6 to 1000 (model units)");
  const detail::Solid& part = *detail::Access::of(solid);
  detail::StoredCoordinate stored = nullptr;
  if (options.format) {
    checkPrecision(part, options.tolerance);
    stored = detail::storedCoordinate(formatOf(*options.format), options.ascii);
  }
  detail::PartMesh made;
  try {
    const detail::CancelScope scope(options.cancel);
    made = detail::meshOfSolid(part, options.tolerance, stored);
  } catch (const detail::Cancelled&) {
    throw Error(ErrorCode::Cancelled, "exportMesh: cancelled");
  } catch (const std::bad_alloc&) {
    throw Error(ErrorCode::OutOfMemory, "out of memory");
  } catch (const std::exception& e) {
    // An unbounded part, a primitive that cannot be meshed, a result that
    // is not a valid mesh: all say why the part cannot be printed.
    throw Error(ErrorCode::NotPrintable, e.what());
  }
  if (made.mesh.empty()) throw Error(ErrorCode::NotPrintable, "the part is empty");
  Mesh mesh;
  mesh.vertices.reserve(made.mesh.points.size());
  for (const detail::dvec3& p : made.mesh.points) mesh.vertices.push_back(toPublic(p));
  mesh.triangles.assign(made.mesh.triangles.begin(), made.mesh.triangles.end());
  mesh.triangleMaterial = made.material;
  for (const detail::MaterialPtr& m : made.materials)
    mesh.materials.push_back(m ? std::optional<Material>(toPublic(*m)) : std::nullopt);
  return mesh;
}

void writeMesh(const Mesh& mesh, const std::string& path, bool ascii) {
  if (mesh.triangles.empty())
    throw Error(ErrorCode::InvalidArgument, "writeMesh: the mesh has no triangles");
  checkIndices(mesh);
  detail::PartMesh part;
  part.mesh = triangleMesh(mesh);
  part.material = mesh.triangleMaterial;
  detail::guarded([&] {
    for (const std::optional<Material>& m : mesh.materials)
      part.materials.push_back(m ? toDetail(*m) : nullptr);
    detail::meshFormatFor(path);  // an unknown extension is a bad argument
  });
  detail::guarded(ErrorCode::IoError, [&] {
    if (std::string problem = detail::outputPathProblem(path); !problem.empty())
      throw std::runtime_error("cannot write " + path + ": " + problem);
    detail::writeMeshFile(path, part, ascii);
  });
}

Mesh readMesh(const std::string& path) {
  const detail::TriangleMesh read = detail::readMeshFileAsError(path);
  Mesh mesh;
  mesh.vertices.reserve(read.points.size());
  for (const detail::dvec3& p : read.points) mesh.vertices.push_back(toPublic(p));
  mesh.triangles.assign(read.triangles.begin(), read.triangles.end());
  return mesh;
}

MeshDefect meshDefect(const Mesh& mesh) {
  const detail::MeshDefect found =
      detail::guarded([&] { return detail::meshDefect(triangleMesh(mesh)); });
  return {kindOf(found.kind), found.text};
}

}  // namespace csgray
