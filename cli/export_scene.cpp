#include "cli/export_scene.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "cli/crash_guard.h"
#include "cli/heap_reserve.h"
#include "cli/warning.h"
#include "export/cgal/mesh_boolean.h"
#include "export/printed_part.h"
#include "io/atomic_file.h"
#include "meshio/mesh_writer.h"
#include "meshio/outline_writer.h"
#include "profile/region_evaluation.h"
#include "scene/region_surface.h"

namespace csgray::detail {

namespace {

// The outline of the scene's 2D regions (their union) as SVG or DXF.
void exportOutline(const Scene& scene, const ExportOptions& options, double scriptSeconds) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<RegionPtr> regions;
  for (const SurfacePtr& surface : scene.surfaces) {
    if (surface->shape() != Surface::Shape::Region) continue;
    RegionPtr region = regionInPlane(*surface);
    if (!region)
      throw std::runtime_error(options.script + ": a " + surface->kind() +
                               " placed in space by a 3D transform has no outline in the plane "
                               "z = 0");
    regions.push_back(std::move(region));
  }
  if (regions.empty())
    throw std::runtime_error(options.script +
                             ": there is no 2D region to outline (.svg and .dxf hold the outlines "
                             "of regions: square{}, circle{}, polygon{}, ...)");
  const std::size_t others = scene.objects.size() + scene.surfaces.size() - regions.size();
  if (others > 0)
    printWarning(options.script + ": " + std::to_string(others) +
                 (others == 1 ? " solid or surface is" : " solids or surfaces are") +
                 " not outlined: only 2D regions are");
  Profile outline;
  try {
    const RegionPtr all =
        regions.size() == 1 ? regions[0] : Region::boolean(Region::Op::Union, regions);
    outline = evaluate(*all, options.tolerance);
  } catch (const std::exception& e) {
    throw std::runtime_error(options.script + ": " + e.what());
  }
  if (options.meshed) options.meshed();
  if (outline.loops.empty()) throw std::runtime_error(options.script + ": the region is empty");
  writeOutlineFile(options.output, outline, options.tolerance);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("csgray: wrote %s (%zu loop%s, area %.6g) in %.2f s\n", options.output.c_str(),
              outline.loops.size(), outline.loops.size() == 1 ? "" : "s", area(outline),
              scriptSeconds + seconds);
}

}  // namespace

void checkExportOutput(const ExportOptions& options) {
  std::error_code same;
  if (std::filesystem::equivalent(options.script, options.output, same))
    throw std::runtime_error("cannot write " + options.output + ": it is the script itself");
  // Where the file would go first (a folder has no extension to speak
  // of), then its format: meshFormatFor throws for an unknown extension.
  if (std::string problem = outputPathProblem(options.output); !problem.empty())
    throw std::runtime_error("cannot write " + options.output + ": " + problem);
  if (outlineFormatFor(options.output)) return;
  try {
    meshFormatFor(options.output);
  } catch (const std::invalid_argument&) {
    // export writes 2D outlines too, which the mesh writer's list leaves out.
    throw std::invalid_argument(
        "cannot write " + options.output + ": unknown mesh format '" +
        std::filesystem::path(options.output).extension().string() +
        "' (use .stl, .obj, .off, .ply or .3mf; .svg or .dxf for a 2D outline)");
  }
}

void exportScene(const Scene& scene, const ExportOptions& options, double scriptSeconds) {
  if (outlineFormatFor(options.output)) {
    exportOutline(scene, options, scriptSeconds);
    return;
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const SolidPtr part = printedPart(scene, options.script, "export", printWarning);
  const MeshFormat format = meshFormatFor(options.output);
  checkFloatPrecision(*part, options.tolerance, options.script);
  // A tenth to a fifth faster (plate(8): 1.03 → 0.85 s; docs/performance.md).
  reserveHugePageHeap(std::size_t(512) << 20);
  MeshBooleanStats counts;
  PartMesh mesh = [&] {
    const CrashGuard guard(options.script);
    try {
      return meshOfSolid(*part, options.tolerance, storedCoordinate(format, options.ascii),
                         &counts);
    } catch (const std::exception& e) {
      throw std::runtime_error(options.script + ": " + e.what());
    }
  }();
  if (options.meshed) options.meshed();
  if (mesh.mesh.empty()) throw std::runtime_error(options.script + ": the part is empty");
  const auto evaluated = Clock::now();
  writeMeshFile(options.output, mesh, options.ascii);
  const auto written = Clock::now();

  auto secs = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  if (options.stats)
    std::fprintf(
        stderr,
        "csgray: stages: script %.3f s, mesh %.3f s, check %.3f s, write %.3f s\n"
        "csgray: %zu primitives tessellated, %zu booleans (%zu in doubles, %zu of them perturbed, "
        "%zu by CGAL%s), %zu "
        "joined without one, %zu "
        "glued face to face, %zu rounding repair%s, %zu contact%s resolved, %zu graze%s cleared, "
        "%zu stray shell%s removed%s\n",
        scriptSeconds, secs(start, evaluated) - counts.checkSeconds, counts.checkSeconds,
        secs(evaluated, written), counts.primitives, counts.corefinements, counts.inDoubles,
        counts.perturbed, counts.corefinements - counts.inDoubles,
        counts.redoneByCgal ? "; the part made again by CGAL alone after a check failed" : "",
        counts.merges, counts.glued, counts.repairs, counts.repairs == 1 ? "" : "s",
        counts.contacts, counts.contacts == 1 ? "" : "s", counts.grazes,
        counts.grazes == 1 ? "" : "s", counts.strayShells, counts.strayShells == 1 ? "" : "s",
        counts.holesFilled   ? "; made on a last try, holes that pins of their radius fill left out"
        : counts.sweepsApart ? "; made on a last try, sweeps of touching regions taken apart"
        : counts.pinchesOpened ? "; made on a last try, regions that touch themselves opened there"
        : counts.cuttersLengthened
            ? "; made on a last try, the cylinders it cuts away a tenth of the tolerance longer"
        : counts.framesAsWritten
            ? "; made on a last try, the turned part's places taken back as written, not snapped"
        : counts.reordered == 0 ? ""
        : counts.reordered == 1 ? "; made on a second try, each union's operands in reverse order"
                                : "; made on a last try, each union's operands shuffled");
  std::printf("csgray: wrote %s (%zu triangles, volume %.6g) in %.2f s\n", options.output.c_str(),
              mesh.mesh.size(), mesh.mesh.volume(), scriptSeconds + secs(start, written));
}

}  // namespace csgray::detail
