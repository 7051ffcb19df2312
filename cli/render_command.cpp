#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/aov_images.h"
#include "cli/commands.h"
#include "cli/heap_reserve.h"
#include "cli/number_checks.h"
#include "cli/progress.h"
#include "cli/warning.h"
#include "cli/watchdog.h"
#include "io/image_file.h"
#include "io/image_formats.h"
#include "raytrace/ray_estimate.h"
#include "raytrace/renderer.h"
#include "scene/value_checks.h"
#include "view/file_watcher.h"

namespace csgray::detail {

namespace {

constexpr int kMaxSide = 16384;
constexpr long kMaxPixels = 64L * 1024 * 1024;

// The most rays a render may trace by the bound of raytrace/ray_estimate.h
// unless --max-rays says otherwise. Every scene in examples/ and in the
// tests is far below it: the largest bound, glass_and_mirror.lua's at
// 1024x768 with 4 samples (the most the docs use), is 4.8e9, since its
// glass lets every ray branch into a tree of 511 (it traces 400 times
// fewer); at the default size and samples 7.4e8. At some ten million rays
// a second on a core, 1e11 is hours of work; the script of 2000 area
// lights of 1024 samples, at 9.8e11, is refused.
constexpr double kDefaultMaxRays = 1e11;

struct RenderArguments {
  std::string output, size = "800x600";
  int threads = 0;
  // None: 1, or for a bare solid (the CAD look) kCadLookSamples, adaptive.
  std::optional<int> samples;
  bool adaptive = false, stats = false, edges = false, watch = false;
  std::vector<std::string> aovs;
  double maxRays = kDefaultMaxRays;  // 0: no limit
};

// Refuses a render whose bound of rays (raytrace/ray_estimate.h) is above
// the limit, before any is traced.
void checkRayBound(const Scene& scene, const RenderOptions& options, double maxRays,
                   const std::string& script) {
  const RayEstimate estimate = estimateRays(scene, options);
  if (!(maxRays > 0.0) || estimate.total() <= maxRays) return;
  char text[96];
  std::snprintf(text, sizeof text, "the render would trace up to %.2g rays (", estimate.total());
  char limit[64];
  std::snprintf(limit, sizeof limit, "); at most %.3g are allowed (--max-rays)", maxRays);
  throw std::runtime_error(script + ": " + text + estimate.factors() + limit);
}

// "1024x768" to width and height; throws CLI::ValidationError.
std::pair<int, int> parseSize(const std::string& text) {
  // Digits, x, digits (scanned by hand: std::regex recurses per character,
  // and a size of a million digits would overflow the stack).
  const std::size_t x = text.find_first_of("xX");
  auto digits = [](std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  const std::string_view all(text);
  if (x == std::string::npos || !digits(all.substr(0, x)) || !digits(all.substr(x + 1)))
    throw CLI::ValidationError(
        "--size", "expected WIDTHxHEIGHT, e.g. 1024x768, got '" + shownValue(text) + "'");
  // A side of more than 6 digits is out of range, whatever its value.
  auto side = [](std::string_view s) {
    return s.size() > 6 ? kMaxSide + 1 : std::stoi(std::string(s));
  };
  const int w = side(all.substr(0, x)), h = side(all.substr(x + 1));
  if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide || long(w) * h > kMaxPixels)
    throw CLI::ValidationError("--size", "image size " + shownValue(text) +
                                             " is out of range (1 to " + std::to_string(kMaxSide) +
                                             " per side, at most " + std::to_string(kMaxPixels) +
                                             " pixels)");
  return {w, h};
}

int renderImage(const RenderArguments& arguments, const PartScript& script) {
  const std::string& output = arguments.output;
  auto [width, height] = parseSize(arguments.size);
  // Refuse an unwritable format before spending time on the render.
  std::error_code same;
  if (std::filesystem::equivalent(script.path(), output, same))
    throw std::runtime_error("cannot write " + output + ": it is the script itself");
  if (arguments.adaptive && arguments.samples && *arguments.samples < 2)
    throw CLI::ValidationError("--adaptive", "needs --samples of 2 or more to spend");
  const std::vector<std::string>& aovs = arguments.aovs;
  bool depthAov = std::count(aovs.begin(), aovs.end(), "depth") > 0;
  bool normalAov = std::count(aovs.begin(), aovs.end(), "normal") > 0;
  std::vector<std::string> outputs{output};
  if (depthAov) outputs.push_back(aovPath(output, "depth"));
  if (normalAov) outputs.push_back(aovPath(output, "normal"));
  for (const std::string& path : outputs) {
    // An AOV's name is made from the output's: it too may not be the script.
    if (std::filesystem::equivalent(script.path(), path, same))
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
  RenderThreads renderThreads(arguments.threads);
  const int workers = renderThreads.size();
  Scene scene = script.run();
  renderThreads.wake();
  using Clock = std::chrono::steady_clock;
  Clock::time_point scripted = Clock::now(), built, traced;
  // A PNG file is compressed band by band on the render's threads as
  // its rows are finished, so that little is left for after the render.
  std::optional<PngEncoder> png;
  if (isPngFile(output)) png.emplace(width, height);
  // Set at the end of --timeout: the renderer stops at the next pixel.
  std::atomic<bool> late = false;
  RenderResult result = [&] {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.threads = arguments.threads;
    options.threadPool = &renderThreads;
    // A bare solid is antialiased unless --samples says otherwise; the
    // samples go to the pixels at edges, which keeps a part's render fast.
    const bool cadSamples = !arguments.samples && scene.cadLook;
    options.samples = arguments.samples.value_or(cadSamples ? kCadLookSamples : 1);
    options.adaptive = arguments.adaptive || cadSamples;
    if (options.adaptive && options.samples < 2)
      throw CLI::ValidationError("--adaptive", "needs --samples of 2 or more to spend");
    options.edges = arguments.edges;
    options.depthAov = depthAov;
    options.normalAov = normalAov;
    options.cancel = &late;
    checkRayBound(scene, options, arguments.maxRays, script.path());
    ProgressBar bar("rendering");
    options.progress = [&bar](double done) { bar.update(done); };
    if (png) {
      options.bandRows = PngEncoder::kBandRows;
      options.rowsDone = [&](const Image& color, int first, int) {
        png->encodeBand(first / PngEncoder::kBandRows,
                        pngRows(color.rgb.data(), color.width, ImageData::LinearColor));
      };
    }
    try {
      // The files are written after the limit: they are whole or not there.
      const Watchdog limit(script.timeLeft(), late);
      Renderer renderer(scene, options);
      built = Clock::now();
      RenderResult r = renderer.renderAll();
      traced = Clock::now();
      renderThreads.finish();  // not spinning while the file is written
      return r;
    } catch (const std::invalid_argument& e) {  // e.g. nothing to frame
      throw std::runtime_error(script.path() + ": " + e.what());
    } catch (const RenderCancelled&) {
      throw std::runtime_error(script.timedOut());
    }
  }();
  // Every image into its temporary first, then all renamed: a failure on
  // any (a full disk) leaves every file as it was, not the depth image new
  // beside an old colour image.
  std::optional<AtomicFile> depthFile, normalFile;
  if (depthAov) {
    const std::string path = aovPath(output, "depth");
    writeAov(depthFile.emplace(path), path, result.depth, true, workers);
  }
  if (normalAov) {
    const std::string path = aovPath(output, "normal");
    writeAov(normalFile.emplace(path), path, result.normal, false, workers);
  }
  const Image& image = result.color;
  AtomicFile colorFile(output);
  writeImageUncommitted(colorFile, output, image.width, image.height, image.rgb.data(),
                        ImageData::LinearColor, workers, png ? &*png : nullptr);
  if (depthFile) depthFile->commit();
  if (normalFile) normalFile->commit();
  colorFile.commit();
  if (arguments.stats) {
    auto secs = [](Clock::time_point a, Clock::time_point b) {
      return std::chrono::duration<double>(b - a).count();
    };
    double trace = secs(built, traced);
    const RayCounts& rays = result.rays;
    std::fprintf(stderr,
                 "csgray: stages: script %.3f s, build %.3f s, trace %.3f s, write %.3f s\n"
                 "csgray: rays: %llu primary (%.2f M/s), %llu shadow (%.2f M/s), %llu "
                 "secondary; %.2f M rays/s in all\n",
                 secs(start, scripted), secs(scripted, built), trace, secs(traced, Clock::now()),
                 (unsigned long long)rays.primary, rays.primary / trace * 1e-6,
                 (unsigned long long)rays.shadow, rays.shadow / trace * 1e-6,
                 (unsigned long long)rays.secondary,
                 (rays.primary + rays.shadow + rays.secondary) / trace * 1e-6);
  }
  std::chrono::duration<double> seconds = Clock::now() - start;
  std::printf("csgray: wrote %s (%dx%d) in %.2f s\n", output.c_str(), width, height,
              seconds.count());
  return 0;
}

// Renders, then again each time the script or a file it read changes,
// until the process is ended. A failed render says why and waits for the
// next change; the image stays as the last good render left it.
int watchRender(const RenderArguments& arguments, const PartScript& script) {
  if (script.runTimeout() > 0.0)
    throw CLI::ValidationError("--watch", "renders until Ctrl-C; --timeout does not go with it");
  PartScript part = script;
  // The files the script reads are noted, to watch them with it.
  auto files = std::make_shared<std::vector<std::string>>();
  part.options().fileRead = [files](const std::string& path) { files->push_back(path); };
  std::mutex mutex;
  std::condition_variable wake;
  bool changed = false;
  FileWatcher watcher([&] {
    std::lock_guard lock(mutex);
    changed = true;
    wake.notify_one();
  });
  std::vector<std::string> watched;
  for (bool first = true;; first = false) {
    files->assign(1, part.path());
    try {
      renderImage(arguments, part);
      watched.clear();
    } catch (const DefineError& e) {
      if (first) throw;  // the command line's -D: as without --watch
      std::fprintf(stderr, "csgray: error: %s\n", terminalLine(e.what()).c_str());
    } catch (const CLI::ValidationError&) {
      throw;  // the options, not the script
    } catch (const std::exception& e) {
      std::fprintf(stderr, "csgray: error: %s\n", terminalLine(e.what()).c_str());
    }
    // After a failure, the files the last good run read stay watched too.
    watched.insert(watched.end(), files->begin(), files->end());
    watcher.watch(watched);
    if (first)
      std::printf("csgray: watching %s for changes (Ctrl-C to stop)\n", part.path().c_str());
    std::fflush(stdout);
    std::unique_lock lock(mutex);
    wake.wait(lock, [&] { return changed; });
    changed = false;
  }
}

}  // namespace

Command renderCommand(CLI::App& app, ScriptArguments& script) {
  auto arguments = std::make_shared<RenderArguments>();
  CLI::App* render = addScriptCommand(app, "render", "Ray trace a part script to an image", script);
  render
      ->add_option("-o,--output", arguments->output,
                   "Image file; its extension picks the format (.png, .exr, ...)")
      ->required();
  render->add_option("--size", arguments->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  render->add_option("--threads", arguments->threads, "Threads to render on (0: one per core)")
      ->check(decimal)
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  render
      ->add_option("--samples", arguments->samples,
                   "Rays per pixel, jittered (antialiasing); default 1, or " +
                       std::to_string(kCadLookSamples) +
                       " with --adaptive for a script that returns a bare solid")
      ->check(decimal)
      ->check(CLI::Range(1, 1024));
  render->add_flag("--stats", arguments->stats,
                   "Print the time of each stage and the rays traced per second to stderr");
  render->add_flag("--adaptive", arguments->adaptive,
                   "Spend the --samples only on pixels at edges; others get one ray");
  render->add_flag("--edges", arguments->edges,
                   "Draw edge lines: outlines and creases (also scene{edges=true})");
  render
      ->add_option("--aov", arguments->aovs,
                   "Also write depth and/or normal images beside the output: depth,normal")
      ->delimiter(',')
      ->check(CLI::IsMember({"depth", "normal"}));
  render
      ->add_option("--max-rays", arguments->maxRays,
                   "Refuse a render that could trace more rays than this (0: no limit)")
      ->check(rayCountRange)
      ->capture_default_str();
  render->add_flag("--watch", arguments->watch,
                   "Render again each time the script or a file it reads changes, until Ctrl-C");
  addScriptOptions(*render, script);
  return {render, [arguments](const PartScript& part) {
            return arguments->watch ? watchRender(*arguments, part) : renderImage(*arguments, part);
          }};
}

}  // namespace csgray::detail
