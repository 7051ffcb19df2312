// csgray: the command line over the modeler, ray tracer and io libraries.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "cli/check_command.h"
#include "cli/heap_reserve.h"
#include "cli/mesh_tools.h"
#include "cli/progress.h"
#include "cli/warning.h"
#include "cli/watchdog.h"
#include "engine/primitive.h"
#include "io/image_file.h"
#include "io/image_formats.h"
#include "raytrace/renderer.h"
#include "script/script.h"

using namespace csgray::detail;

namespace {

constexpr int kMaxSide = 16384;
constexpr long kMaxPixels = 64L * 1024 * 1024;

// "1024x768" to width and height; throws CLI::ValidationError.
std::pair<int, int> parseSize(const std::string& text) {
  std::smatch m;
  if (!std::regex_match(text, m, std::regex(R"((\d{1,6})[xX](\d{1,6}))")))
    throw CLI::ValidationError("--size",
                               "expected WIDTHxHEIGHT, e.g. 1024x768, got '" + text + "'");
  int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide || long(w) * h > kMaxPixels)
    throw CLI::ValidationError("--size", "image size " + text + " is out of range (1 to " +
                                             std::to_string(kMaxSide) + " per side, at most " +
                                             std::to_string(kMaxPixels) + " pixels)");
  return {w, h};
}

// -D name=value pairs.
std::vector<std::pair<std::string, std::string>> parseDefines(
    const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> defines;
  for (const std::string& item : items) {
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw CLI::ValidationError("-D", "expected name=value, got '" + item + "'");
    defines.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return defines;
}

std::string formatPoint(const dvec3& p) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%g, %g, %g]", p.x, p.y, p.z);
  return buffer;
}

void printInfo(const std::string& script, const Scene& scene) {
  TreeStats stats;
  for (const SolidPtr& object : scene.objects) {
    TreeStats s = treeStats(*object);
    stats.primitives += s.primitives;
    stats.booleans += s.booleans;
  }
  Bounds b = scene.bounds();
  std::cout << script << "\n";
  if (b.empty()) {
    std::cout << "  bounds:        empty\n";
  } else {
    std::cout << "  bounds:        " << formatPoint(b.lo) << " .. " << formatPoint(b.hi) << "\n";
    if (b.finite()) std::cout << "  size:          " << formatPoint(b.size()) << "\n";
  }
  std::cout << "  objects:       " << scene.objects.size() << "\n"
            << "  primitives:    " << stats.primitives << "\n"
            << "  boolean nodes: " << stats.booleans << "\n"
            << "  surfaces:      " << scene.surfaces.size() << "\n"
            << "  lights:        " << scene.lights.size()
            << (scene.lights.empty() ? " (default)" : "") << "\n"
            << "  camera:        " << (scene.camera ? "set" : "framed from bounds") << "\n";
}

// The names of the AOV images beside the colour image: out.png gives
// out.depth.png and out.normal.png.
std::string aovPath(const std::string& output, const std::string& aov) {
  std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + "." + aov + p.extension().string())).string();
}

// Depth and normal images. Float formats keep the values (depth in model
// units, +inf where nothing was hit; normals in [-1, 1]); 8-bit formats get
// a picture of them: depth as nearest / depth (white at the nearest
// surface, black where nothing was hit), normals as (n + 1) / 2.
void writeAov(const std::string& path, Image image, bool isDepth, int threads) {
  if (!keepsFloatValues(path)) {
    if (isDepth) {
      // nearest / depth: 1 at the nearest surface, fading with distance,
      // so an infinite floor does not squeeze the part into one grey.
      float nearest = INFINITY;
      for (float v : image.rgb)
        if (v > 0.0f) nearest = std::min(nearest, v);
      for (float& v : image.rgb) v = v > 0.0f && std::isfinite(v) ? nearest / v : 0.0f;
    } else {
      for (float& v : image.rgb) v = v == 0.0f ? 0.0f : 0.5f * (v + 1.0f);
    }
  }
  writeImage(path, image.width, image.height, image.rgb.data(), ImageData::Values, threads);
}

}  // namespace

// 0 (no limit) up to about eleven days; NaN is refused.
const CLI::Validator timeoutRange(
    [](const std::string& text) -> std::string {
      double v = std::strtod(text.c_str(), nullptr);
      return v >= 0.0 && v <= 1e6 ? "" : "must be a number of seconds from 0 to 1e6";
    },
    "SECONDS");

// Digits only: CLI11 would read 0x10 as sixteen and 010 as eight.
const CLI::Validator decimal(
    [](const std::string& text) -> std::string {
      bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      return digits && !(text.size() > 1 && text[0] == '0') ? "" : "must be a whole number";
    },
    "N");

// 1e-6 to 1000 model units; NaN and words are refused.
const CLI::Validator toleranceRange(
    [](const std::string& text) -> std::string {
      char* end = nullptr;
      double v = std::strtod(text.c_str(), &end);
      return end != text.c_str() && *end == '\0' && v >= 1e-6 && v <= 1e3
                 ? ""
                 : "must be a number from 1e-6 to 1000 (model units)";
    },
    "TOLERANCE");

// 0 to 10⁶ model units; NaN and words are refused (CLI::Range lets NaN by).
const CLI::Validator lengthRange(
    [](const std::string& text) -> std::string {
      char* end = nullptr;
      double v = std::strtod(text.c_str(), &end);
      return end != text.c_str() && *end == '\0' && v >= 0.0 && v <= 1e6
                 ? ""
                 : "must be a number from 0 to 1e6 (model units)";
    },
    "LENGTH");

int main(int argc, char** argv) {
  CLI::App app{"csgray: exact CSG ray tracing of parts written in Lua"};
  // The version and the instruction set the build is for (CMakeLists.txt,
  // CSGRAY_ARCH): a v3 binary runs only on processors that have it.
#if defined(CSGRAY_X86_64_V3)
  app.set_version_flag("--version", std::string(CSGRAY_VERSION) + " (x86-64-v3)");
#else
  app.set_version_flag("--version", std::string(CSGRAY_VERSION) + " (portable)");
#endif
  app.require_subcommand(1);

  std::string script, output, size = "800x600";
  std::vector<std::string> defineItems;
  int threads = 0, samples = 1;
  bool adaptive = false, stats = false;
  std::vector<std::string> aovs;
  double scriptTimeout = 60.0;
  std::vector<std::string> allowedFolders;
  ExportOptions exportOptions;

  CLI::App* render = app.add_subcommand("render", "Ray trace a part script to an image");
  render->add_option("script", script, "Lua part script")->required();
  render
      ->add_option("-o,--output", output,
                   "Image file; its extension picks the format (.png, .exr, ...)")
      ->required();
  render->add_option("--size", size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_option("--threads", threads, "Threads to render on (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  render->add_option("--samples", samples, "Rays per pixel, jittered (antialiasing)")
      ->check(decimal)
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  render->add_flag("--stats", stats,
                   "Print the time of each stage and the rays traced per second to stderr");
  render->add_flag("--adaptive", adaptive,
                   "Spend the --samples only on pixels at edges; others get one ray");
  render
      ->add_option("--aov", aovs,
                   "Also write depth and/or normal images beside the output: depth,normal")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal"}));
  render->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  render->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
  const char* allowHelp =
      "A folder outside the script's that its files (meshes, images) may come from";
  render->add_option("--allow-path", allowedFolders, allowHelp)->check(CLI::ExistingDirectory);

  CLI::App* exporter =
      app.add_subcommand("export", "Write a part script's solids as a closed, printable mesh");
  exporter->add_option("script", script, "Lua part script")->required();
  exporter
      ->add_option("-o,--output", exportOptions.output,
                   "Mesh file; its extension picks the format (.stl, .obj, .off, .ply, .3mf)")
      ->required();
  exporter
      ->add_option("--tolerance", exportOptions.tolerance,
                   "Largest distance of the mesh from the exact surface, in model units")
      ->check(toleranceRange)
      ->capture_default_str();
  exporter->add_flag("--ascii", exportOptions.ascii, "Write STL and PLY as text");
  exporter->add_flag("--stats", exportOptions.stats,
                     "Print the time of each stage and the booleans done to stderr");
  exporter->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  exporter
      ->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
  exporter->add_option("--allow-path", allowedFolders, allowHelp)->check(CLI::ExistingDirectory);

  CheckCommandOptions checkOptions;
  CLI::App* checker = app.add_subcommand(
      "check", "Hold a part's exported mesh against its exact model, and report on its booleans");
  checker->add_option("script", script, "Lua part script")->required();
  checker
      ->add_option("--samples", checkOptions.check.samples,
                   "Random points classified by both the exact model and the mesh")
      ->check(decimal)
      ->check(CLI::Range(std::size_t(0), CheckOptions::kMaxSamples))
      ->capture_default_str();
  checker
      ->add_option("--tolerance", checkOptions.check.tolerance,
                   "Tolerance of the export, in model units")
      ->check(toleranceRange)
      ->capture_default_str();
  checker
      ->add_option("--min-wall", checkOptions.check.minWall,
                   "Warn of solid walls thinner than this (model units)")
      ->check(lengthRange)
      ->capture_default_str();
  checker
      ->add_option("--min-gap", checkOptions.check.minGap,
                   "Warn of empty gaps narrower than this (model units)")
      ->check(lengthRange)
      ->capture_default_str();
  checker
      ->add_option("--grid", checkOptions.check.grid,
                   "Rays per side of each of the three ray grids along x, y and z")
      ->check(decimal)
      ->check(CLI::Range(2, CheckOptions::kMaxGrid))
      ->capture_default_str();
  checker->add_option("--seed", checkOptions.check.seed, "Seed of the random points and rays")
      ->check(decimal)
      ->capture_default_str();
  checker->add_flag("--strict", checkOptions.check.strict, "Fail on warnings too");
  checker->add_flag("--json", checkOptions.json, "Print the report as JSON");
  checker->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  checker->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
  checker->add_option("--allow-path", allowedFolders, allowHelp)->check(CLI::ExistingDirectory);

  CLI::App* info = app.add_subcommand("info", "Print the bounds and tree size of a part script");
  info->add_option("script", script, "Lua part script")->required();
  info->add_option("-D", defineItems, "Set a script global before it runs: name=value");
  info->add_option("--script-timeout", scriptTimeout, "Seconds the script may run (0: no limit)")
      ->check(timeoutRange)
      ->capture_default_str();
  info->add_option("--allow-path", allowedFolders, allowHelp)->check(CLI::ExistingDirectory);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "csgray: error: " << e.what() << " (see csgray --help)\n";
    return 2;
  }

  try {
    ScriptOptions scriptOptions;
    scriptOptions.defines = parseDefines(defineItems);
    scriptOptions.loadImage = readTextureImage;
    scriptOptions.loadMesh = [](const std::string& path, bool repair, std::string& report) {
      return meshTools().importMesh(path, repair, report);
    };
    scriptOptions.checkSolid = [](const Solid& solid, const CheckOptions& options) {
      return meshTools().checkPart(solid, options);
    };
    scriptOptions.allowedFolders = allowedFolders;
    scriptOptions.warn = printWarning;
    // Runs the script under the watchdog: nothing is written meanwhile.
    auto runScript = [&] {
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", scriptTimeout);
      Watchdog watchdog(scriptTimeout, script + ": the script did not finish within " + limit +
                                           " s (--script-timeout)");
      return runScriptFile(script, scriptOptions);
    };
    if (*render) {
      auto [width, height] = parseSize(size);
      // Refuse an unwritable format before spending time on the render.
      std::error_code same;
      if (std::filesystem::equivalent(script, output, same))
        throw std::runtime_error("cannot write " + output + ": it is the script itself");
      if (adaptive && samples < 2)
        throw CLI::ValidationError("--adaptive", "needs --samples of 2 or more to spend");
      bool depthAov = std::count(aovs.begin(), aovs.end(), "depth") > 0;
      bool normalAov = std::count(aovs.begin(), aovs.end(), "normal") > 0;
      std::vector<std::string> outputs{output};
      if (depthAov) outputs.push_back(aovPath(output, "depth"));
      if (normalAov) outputs.push_back(aovPath(output, "normal"));
      for (const std::string& path : outputs) {
        // An AOV's name is made from the output's: it too may not be the script.
        if (std::filesystem::equivalent(script, path, same))
          throw std::runtime_error("cannot write " + path + ": it is the script itself");
        if (std::string problem = imageOutputProblem(path); !problem.empty())
          throw std::runtime_error("cannot write " + path + ": " + problem);
      }
      auto start = std::chrono::steady_clock::now();
      // The script's solids and the images come from huge pages: on a
      // virtual machine a 4 KiB page fault costs about 12 µs, and a render
      // touched some 4 000 pages (plate(8): 0.05 s of 0.26 s).
      reserveHugePageHeap(std::size_t(256) << 20);
      // Formats other than PNG go through OpenImageIO, whose many libraries
      // load on another thread while the script runs and the image renders.
      std::optional<ImageFormatsPreload> preload;
      if (!isPngFile(output)) preload.emplace();
      // The render's threads start while the script runs, and wake when it
      // is done, to spin while the renderer is made.
      RenderThreads renderThreads(threads);
      const int workers = renderThreads.size();
      Scene scene = runScript();
      renderThreads.wake();
      using Clock = std::chrono::steady_clock;
      Clock::time_point scripted = Clock::now(), built, traced;
      // A PNG file is compressed band by band on the render's threads as
      // its rows are finished, so that little is left for after the render.
      std::optional<PngEncoder> png;
      if (isPngFile(output)) png.emplace(width, height);
      RenderResult result = [&] {
        ProgressBar bar("rendering");
        RenderOptions options;
        options.width = width;
        options.height = height;
        options.threads = threads;
        options.threadPool = &renderThreads;
        options.samples = samples;
        options.adaptive = adaptive;
        options.depthAov = depthAov;
        options.normalAov = normalAov;
        options.progress = [&bar](double done) { bar.update(done); };
        if (png) {
          options.bandRows = PngEncoder::kBandRows;
          options.rowsDone = [&](const Image& color, int first, int) {
            png->encodeBand(first / PngEncoder::kBandRows,
                            pngRows(color.rgb.data(), color.width, ImageData::LinearColor));
          };
        }
        try {
          Renderer renderer(scene, options);
          built = Clock::now();
          RenderResult r = renderer.renderAll();
          traced = Clock::now();
          renderThreads.finish();  // not spinning while the file is written
          return r;
        } catch (const std::invalid_argument& e) {  // e.g. nothing to frame
          throw std::runtime_error(script + ": " + e.what());
        }
      }();
      if (depthAov) writeAov(aovPath(output, "depth"), result.depth, true, workers);
      if (normalAov) writeAov(aovPath(output, "normal"), result.normal, false, workers);
      const Image& image = result.color;
      writeImage(output, image.width, image.height, image.rgb.data(), ImageData::LinearColor,
                 workers, png ? &*png : nullptr);
      if (stats) {
        auto secs = [](Clock::time_point a, Clock::time_point b) {
          return std::chrono::duration<double>(b - a).count();
        };
        double trace = secs(built, traced);
        const RayCounts& rays = result.rays;
        std::fprintf(stderr,
                     "csgray: stages: script %.3f s, build %.3f s, trace %.3f s, write %.3f s\n"
                     "csgray: rays: %llu primary (%.2f M/s), %llu shadow (%.2f M/s), %llu "
                     "secondary; %.2f M rays/s in all\n",
                     secs(start, scripted), secs(scripted, built), trace,
                     secs(traced, Clock::now()), (unsigned long long)rays.primary,
                     rays.primary / trace * 1e-6, (unsigned long long)rays.shadow,
                     rays.shadow / trace * 1e-6, (unsigned long long)rays.secondary,
                     (rays.primary + rays.shadow + rays.secondary) / trace * 1e-6);
      }
      std::chrono::duration<double> seconds = Clock::now() - start;
      std::printf("csgray: wrote %s (%dx%d) in %.2f s\n", output.c_str(), width, height,
                  seconds.count());
    } else if (*exporter) {
      exportOptions.script = script;
      meshTools().checkExportOutput(exportOptions);
      auto start = std::chrono::steady_clock::now();
      Scene scene = runScript();
      meshTools().exportScene(
          scene, exportOptions,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    } else if (*checker) {
      checkOptions.script = script;
      return meshTools().checkScene(runScript(), checkOptions);
    } else if (*info) {
      printInfo(script, runScript());
    }
  } catch (const CLI::ValidationError& e) {
    std::cerr << "csgray: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';  // one line, whatever a library said
    std::cerr << "csgray: error: " << message << "\n";
    return 1;
  }
  return 0;
}
