#include "cli/export_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "cli/crash_guard.h"
#include "cli/heap_reserve.h"
#include "io/atomic_file.h"
#include "export/cgal/mesh_boolean.h"
#include "meshfile/mesh_writer.h"
#include "engine/boolean.h"

namespace csgray::detail {

void checkExportOutput(const ExportOptions& options) {
  meshFormatFor(options.output);  // throws for an unknown extension
  std::error_code same;
  if (std::filesystem::equivalent(options.script, options.output, same))
    throw std::runtime_error("cannot write " + options.output + ": it is the script itself");
  if (std::string problem = outputPathProblem(options.output); !problem.empty())
    throw std::runtime_error("cannot write " + options.output + ": " + problem);
}

SolidPtr printedPart(const Scene& scene, const std::string& script, const char* verb) {
  if (scene.objects.empty())
    throw std::runtime_error(script + ": there is no solid to " + verb +
                             " (open surfaces cannot be printed)");
  if (!scene.surfaces.empty())
    std::fprintf(stderr, "csgray: warning: %s: %zu open surface%s not %sed: only solids are\n",
                 script.c_str(), scene.surfaces.size(),
                 scene.surfaces.size() == 1 ? " is" : "s are", verb);
  return scene.objects.size() == 1 ? scene.objects[0] : unionOf(scene.objects);
}

void exportScene(const Scene& scene, const ExportOptions& options, double scriptSeconds) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const SolidPtr part = printedPart(scene, options.script, "export");

  const MeshFormat format = meshFormatFor(options.output);
  // Far from the origin a 32-bit float (every format here stores floats)
  // cannot hold the tolerance: half its spacing at |x| is |x|·2⁻²⁴.
  const Bounds box = part->bounds();
  if (box.finite()) {
    double reach = 0.0;
    for (int a = 0; a < 3; ++a) reach = std::max({reach, std::abs(box.lo[a]), std::abs(box.hi[a])});
    const double precision = std::ldexp(reach, -24);
    if (precision > 0.5 * options.tolerance) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "%s: the part reaches %g from the origin, where the file's 32-bit floats are "
                    "good to %.2g only, coarser than half the tolerance %g; move it nearer the "
                    "origin or give a larger tolerance",
                    options.script.c_str(), reach, precision, options.tolerance);
      throw std::runtime_error(text);
    }
  }
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
        "csgray: %zu primitives tessellated, %zu booleans, %zu joined without one, %zu "
        "glued face to face, %zu rounding repair%s, %zu contact%s resolved, %zu stray shell%s "
        "removed\n",
        scriptSeconds, secs(start, evaluated) - counts.checkSeconds, counts.checkSeconds,
        secs(evaluated, written), counts.primitives, counts.corefinements, counts.merges,
        counts.glued, counts.repairs, counts.repairs == 1 ? "" : "s", counts.contacts,
        counts.contacts == 1 ? "" : "s", counts.strayShells, counts.strayShells == 1 ? "" : "s");
  std::printf("csgray: wrote %s (%zu triangles, volume %.6g) in %.2f s\n", options.output.c_str(),
              mesh.mesh.size(), mesh.mesh.volume(), scriptSeconds + secs(start, written));
}

}  // namespace csgray::detail
