#include "export/cgal/mesh_repair.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>

#include <set>
#include <vector>

namespace csgray::detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Adds "did 3 things" to the report when something was done.
void note(std::string& report, std::size_t count, const std::string& verb,
          const std::string& singular, const std::string& plural) {
  if (count == 0) return;
  if (!report.empty()) report += ", ";
  report += verb + " " + std::to_string(count) + " " + (count == 1 ? singular : plural);
}

bool hasRepeatedVertex(const Polygon& polygon) {
  for (std::size_t i = 0; i < polygon.size(); ++i)
    for (std::size_t j = i + 1; j < polygon.size(); ++j)
      if (polygon[i] == polygon[j]) return true;
  return false;
}

// Does the polygon run from point a to point b (by position)?
bool runsFrom(const std::vector<Point>& points, const Polygon& polygon, const Point& a,
              const Point& b) {
  for (std::size_t k = 0; k < polygon.size(); ++k)
    if (points[polygon[k]] == a && points[polygon[(k + 1) % polygon.size()]] == b) return true;
  return false;
}

}  // namespace

TriangleMesh repairMesh(const TriangleMesh& mesh, std::string& report) {
  report.clear();
  std::vector<Point> points;
  points.reserve(mesh.points.size());
  for (const dvec3& p : mesh.points) points.emplace_back(p.x, p.y, p.z);
  std::vector<Polygon> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    if (t[0] < points.size() && t[1] < points.size() && t[2] < points.size())
      polygons.push_back({t[0], t[1], t[2]});

  // The polygon soup: one point per position, no face that uses a vertex
  // twice, no face twice (a face and its reverse count as one).
  note(report, PMP::merge_duplicate_points_in_polygon_soup(points, polygons), "merged",
       "duplicated vertex", "duplicated vertices");
  const std::size_t before = polygons.size();
  std::erase_if(polygons, hasRepeatedVertex);
  note(report, before - polygons.size(), "removed", "face that uses a vertex twice",
       "faces that use a vertex twice");
  note(report, PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons), "removed",
       "duplicated face", "duplicated faces");

  // Consistent orientation across each edge; a vertex where the surface
  // touches itself is split into one per fan.
  const std::vector<Polygon> unoriented = polygons;
  const std::size_t pointsBefore = points.size();
  PMP::orient_polygon_soup(points, polygons);
  std::size_t turned = 0;
  for (std::size_t i = 0; i < polygons.size(); ++i)
    turned += !runsFrom(points, polygons[i], points[unoriented[i][0]], points[unoriented[i][1]]);
  note(report, turned, "turned", "face to match its neighbours", "faces to match their neighbours");
  note(report, points.size() - pointsBefore, "split", "non-manifold vertex",
       "non-manifold vertices");

  Surface surface;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
  note(report, PMP::stitch_borders(surface), "stitched", "edge", "edges");
  const std::size_t faces = surface.number_of_faces();
  PMP::remove_degenerate_faces(surface);
  surface.collect_garbage();
  note(report, faces - surface.number_of_faces(), "removed", "degenerate face", "degenerate faces");

  // Shells face out and cavities in; that needs closed shells that do not
  // cross, which is left for the validity check to say otherwise. Nothing
  // may be left (every face degenerate): CGAL's orientation then crashes.
  if (surface.number_of_faces() > 0 && CGAL::is_closed(surface) &&
      !PMP::does_self_intersect(surface)) {
    std::vector<std::pair<Surface::Vertex_index, Surface::Vertex_index>> firstEdge;
    for (auto f : surface.faces())
      firstEdge.emplace_back(surface.source(surface.halfedge(f)),
                             surface.target(surface.halfedge(f)));
    PMP::orient_to_bound_a_volume(surface);
    auto component = surface.add_property_map<Surface::Face_index, std::size_t>("f:cc").first;
    PMP::connected_components(surface, component);
    std::set<std::size_t> reversedShells;
    std::size_t reversedFaces = 0;
    for (auto f : surface.faces()) {
      // A reversed face has the opposite halfedge of its old first edge.
      auto [s, t] = firstEdge[std::size_t(f)];
      auto h = surface.halfedge(s, t);
      if (h != Surface::null_halfedge() && surface.face(h) == f) continue;
      ++reversedFaces;
      reversedShells.insert(component[f]);
    }
    if (!reversedShells.empty())
      note(report, reversedShells.size(), "reversed",
           "shell (" + std::to_string(reversedFaces) + " faces)",
           "shells (" + std::to_string(reversedFaces) + " faces)");
  }

  note(
      report,
      surface.number_of_vertices() -
          [&] {
            std::size_t used = 0;
            for (auto v : surface.vertices()) used += !surface.is_isolated(v);
            return used;
          }(),
      "removed", "unused vertex", "unused vertices");
  PMP::remove_isolated_vertices(surface);
  surface.collect_garbage();

  TriangleMesh repaired;
  repaired.points.reserve(surface.number_of_vertices());
  for (auto v : surface.vertices()) {
    const Point& p = surface.point(v);
    repaired.points.push_back(dvec3(p.x(), p.y(), p.z()));
  }
  for (auto f : surface.faces()) {
    TriangleMesh::Triangle t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(surface.halfedge(f), surface))
      if (k < 3) t[k++] = std::uint32_t(v);
    if (k == 3) repaired.triangles.push_back(t);
  }
  return repaired;
}

}  // namespace csgray::detail
