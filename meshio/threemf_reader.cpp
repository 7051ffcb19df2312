// read3mf: a 3MF file's build as one triangle mesh, read by lib3mf from
// memory. Every build item's object, placed by the item's transform; a
// components object's components, each placed by its own transform within
// it (3MF Consortium, "3D Manufacturing Format, Core Specification" 1.2,
// §3.4 and §4.2). Points are in the file's unit, taken as the model's.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/printable_token.h"
#include "meshio/lib3mf_handle.h"
#include "meshio/mesh_reader.h"
#include "meshio/reader_common.h"

namespace csgray::detail {

using namespace mesh_reading;

namespace {

// How deep components may nest: an object that holds itself through its
// components would otherwise recurse without end.
constexpr int kMaxComponentDepth = 16;

// A point mapped by a 3MF transform: the specification's matrix (§3.3)
// takes a point as the row vector (x, y, z, 1) times its 4 × 3 matrix;
// lib3mf hands it over transposed, m_fFields[i] the row that gives the
// i-th coordinate, the translation last.
struct Transform {
  std::array<std::array<double, 4>, 3> rows{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Transform of(const NMR::MODELTRANSFORM& t) {
    Transform out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) out.rows[i][j] = double(t.m_fFields[i][j]);
    return out;
  }
  dvec3 operator()(const dvec3& p) const {
    dvec3 q;
    for (int i = 0; i < 3; ++i)
      q[i] = rows[i][0] * p.x + rows[i][1] * p.y + rows[i][2] * p.z + rows[i][3];
    return q;
  }
  // Does it mirror (a negative determinant)? Faces then turn inside out.
  bool mirrors() const {
    const auto& m = rows;
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]) <
           0.0;
  }
  // This transform after `inner` (a component's, within its object).
  Transform after(const Transform& inner) const {
    Transform out;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) {
        double sum = j == 3 ? rows[i][3] : 0.0;
        for (int k = 0; k < 3; ++k) sum += rows[i][k] * inner.rows[k][j];
        out.rows[i][j] = sum;
      }
    return out;
  }
};

class Reader {
 public:
  Reader(const std::string& name, const MeshReadLimits& limits)
      : name_(name), builder_(name, limits) {}

  TriangleMesh read(std::string_view bytes) {
    using namespace NMR;
    Released model, reader, items;
    check(lib3mf_createmodel(&model.object), "create a model", nullptr);
    check(lib3mf_model_queryreader(model.object, "3mf", &reader.object), "create a reader",
          model.object);
    // lib3mf takes the bytes as BYTE*, but only reads them.
    auto* data = reinterpret_cast<BYTE*>(const_cast<char*>(bytes.data()));
    if (lib3mf_reader_readfrombuffer(reader.object, data, bytes.size()) != LIB3MF_OK)
      fail(name_, "not a 3MF file lib3mf can read" + lastError(reader.object));
    check(lib3mf_model_getbuilditems(model.object, &items.object), "list the build", model.object);
    for (BOOL more = false;
         lib3mf_builditemiterator_movenext(items.object, &more) == LIB3MF_OK && more;) {
      Released item, object;
      check(lib3mf_builditemiterator_getcurrent(items.object, &item.object), "read the build",
            items.object);
      check(lib3mf_builditem_getobjectresource(item.object, &object.object),
            "read a build item's object", item.object);
      Transform placed;
      BOOL transformed = false;
      if (lib3mf_builditem_hasobjecttransform(item.object, &transformed) == LIB3MF_OK &&
          transformed) {
        MODELTRANSFORM t;
        check(lib3mf_builditem_getobjecttransform(item.object, &t), "read a transform",
              item.object);
        placed = Transform::of(t);
      }
      add(object.object, placed, 0);
    }
    return builder_.finish();
  }

 private:
  // The library's own words for its last error on `object`, as " (...)".
  static std::string lastError(NMR::PLib3MFBase* object) {
    DWORD code = 0;
    LPCSTR text = nullptr;
    if (object && NMR::lib3mf_getlasterror(object, &code, &text) == LIB3MF_OK && text && *text)
      return std::string(" (") + printableToken(text, 120) + ")";
    return "";
  }

  void check(LIB3MFRESULT result, const char* what, NMR::PLib3MFBase* object) const {
    if (result != LIB3MF_OK)
      fail(name_, std::string("lib3mf could not ") + what + lastError(object));
  }

  void add(NMR::PLib3MFBase* object, const Transform& placed, int depth) {
    using namespace NMR;
    if (depth > kMaxComponentDepth)
      fail(name_, "components nested deeper than " + std::to_string(kMaxComponentDepth) +
                      " (an object that holds itself?)");
    BOOL isMesh = false, isComponents = false;
    check(lib3mf_object_ismeshobject(object, &isMesh), "read an object", object);
    if (isMesh) return addMesh(object, placed);
    check(lib3mf_object_iscomponentsobject(object, &isComponents), "read an object", object);
    if (!isComponents) return;  // neither: nothing of it is a solid
    DWORD count = 0;
    check(lib3mf_componentsobject_getcomponentcount(object, &count), "read components", object);
    for (DWORD i = 0; i < count; ++i) {
      Released component, child;
      check(lib3mf_componentsobject_getcomponent(object, i, &component.object), "read a component",
            object);
      check(lib3mf_component_getobjectresource(component.object, &child.object),
            "read a component's object", component.object);
      MODELTRANSFORM t;
      check(lib3mf_component_gettransform(component.object, &t), "read a transform",
            component.object);
      add(child.object, placed.after(Transform::of(t)), depth + 1);
    }
  }

  void addMesh(NMR::PLib3MFBase* object, const Transform& placed) {
    using namespace NMR;
    DWORD vertexCount = 0, triangleCount = 0;
    check(lib3mf_meshobject_getvertexcount(object, &vertexCount), "read a mesh", object);
    check(lib3mf_meshobject_gettrianglecount(object, &triangleCount), "read a mesh", object);
    std::vector<MODELMESHVERTEX> vertices(vertexCount);
    std::vector<MODELMESHTRIANGLE> triangles(triangleCount);
    if (vertexCount)
      check(lib3mf_meshobject_getvertices(object, vertices.data(), vertexCount, nullptr),
            "read a mesh's vertices", object);
    if (triangleCount)
      check(lib3mf_meshobject_gettriangleindices(object, triangles.data(), triangleCount, nullptr),
            "read a mesh's triangles", object);
    // Vertices as the triangles use them: one no triangle uses is no
    // point of the mesh.
    std::vector<std::int64_t> index(vertexCount, -1);
    auto point = [&](DWORD v) {
      if (index[v] < 0) {
        const dvec3 p = placed(dvec3(vertices[v].m_fPosition[0], vertices[v].m_fPosition[1],
                                     vertices[v].m_fPosition[2]));
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          fail(name_, "vertex " + std::to_string(v) + " is not finite");
        index[v] = builder_.vertex(p);
      }
      return std::uint32_t(index[v]);
    };
    const bool mirrored = placed.mirrors();
    for (DWORD t = 0; t < triangleCount; ++t) {
      const DWORD* corner = triangles[t].m_nIndices;
      for (int k = 0; k < 3; ++k)
        if (corner[k] >= vertexCount)
          fail(name_, "triangle " + std::to_string(t) + ": vertex index " +
                          std::to_string(corner[k]) + " is out of range (" +
                          std::to_string(vertexCount) + " vertices)");
      const std::uint32_t a = point(corner[0]), b = point(corner[1]), c = point(corner[2]);
      if (mirrored)
        builder_.triangle(a, c, b);
      else
        builder_.triangle(a, b, c);
    }
  }

  const std::string& name_;
  MeshBuilder builder_;
};

}  // namespace

TriangleMesh read3mf(std::string_view bytes, const std::string& name,
                     const MeshReadLimits& limits) {
  checkSize(bytes, name, limits);
  return Reader(name, limits).read(bytes);
}

}  // namespace csgray::detail
