#include "view/view_session.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "check/exact_volume.h"
#include "engine/primitive.h"
#include "io/image_file.h"
#include "io/png_file.h"
#include "raytrace/renderer.h"
#include "scene/camera.h"
#include "view/view_frame.h"

namespace csgray::detail {

namespace {

// Rays per side of the grids of the info panel's volume: 3 · 128² rays, a
// few milliseconds, within a fraction of a percent on a typical part.
constexpr int kVolumeGrid = 128;

double sceneVolume(const Scene& scene) {
  double volume = 0.0;
  for (const SolidPtr& object : scene.objects) {
    if (!object->bounds().finite()) return 0.0;
    volume += exactVolume(*object, kVolumeGrid);
  }
  return volume;
}

}  // namespace

ViewSession::ViewSession(std::string script, ScriptOptions options, int threads,
                         ScriptRunner runner)
    : script_(std::move(script)),
      options_(std::move(options)),
      runner_(runner ? std::move(runner) : ScriptRunner(runScriptFile)),
      threads_(threads) {
  std::string refused = run(options_.defines);
  if (!refused.empty()) throw DefineError(refused);  // the command line's -D
}

ViewSession::~ViewSession() { shutdown(); }

std::string ViewSession::run(const std::vector<std::pair<std::string, std::string>>& defines) {
  std::lock_guard running(runMutex_);
  // The files the script reads are watched with it: fileRead notes them.
  auto files = std::make_shared<std::vector<std::string>>(1, script_);
  ScriptOptions options = options_;
  options.defines = defines;
  options.fileRead = [files](const std::string& path) { files->push_back(path); };
  std::shared_ptr<const Scene> scene;
  std::vector<Parameter> parameters;
  std::string error;
  double volume = 0.0;
  Bounds bounds;
  try {
    parameters = scriptFileParameters(script_);
    Scene ran = runner_(script_, options);
    checkHasObjects(ran);
    volume = sceneVolume(ran);
    bool metNothing = false;
    bounds = ran.partBounds(&metNothing);
    if (metNothing) bounds = Bounds();  // an empty part has no box to show
    // Once, not at each frame: some 50 000 rays a solid.
    ran.framedBox = ran.framedBounds(bounds);
    scene = std::make_shared<const Scene>(std::move(ran));
  } catch (const DefineError& e) {
    return e.what();  // nothing changes
  } catch (const std::exception& e) {
    error = e.what();
    if (error.find(script_) != 0) error = script_ + ": " + error;
  }
  std::lock_guard lock(stateMutex_);
  nextVersion();
  state_.error = error;
  state_.defines = defines;
  std::sort(files->begin(), files->end());
  files->erase(std::unique(files->begin(), files->end()), files->end());
  // A failed run may stop before it reads a file the good one read: keep
  // watching those too, so that fixing either is seen.
  if (!error.empty())
    for (const std::string& f : state_.files)
      if (!std::binary_search(files->begin(), files->end(), f)) files->push_back(f);
  state_.files = *files;
  if (scene) {
    state_.scene = scene;
    state_.parameters = std::move(parameters);
    state_.volume = volume;
    state_.bounds = bounds;
  }
  changed_.notify_all();
  return {};
}

void ViewSession::nextVersion() {
  ++state_.version;
  if (outdated_) *outdated_ = true;
  state_.outdated = outdated_ = std::make_shared<std::atomic<bool>>(false);
}

void ViewSession::reload() {
  // A value the script's new annotations refuse: the page says so.
  const std::string refused = run(state().defines);
  if (refused.empty()) return;
  std::lock_guard lock(stateMutex_);
  nextVersion();
  state_.error = refused;
  changed_.notify_all();
}

std::string ViewSession::define(const std::string& name, const std::optional<std::string>& value) {
  std::vector<std::pair<std::string, std::string>> defines = state().defines;
  std::erase_if(defines, [&](const auto& d) { return d.first == name; });
  if (value) defines.emplace_back(name, *value);
  return run(defines);
}

SessionState ViewSession::state() const {
  std::lock_guard lock(stateMutex_);
  return state_;
}

SessionState ViewSession::waitForChange(std::uint64_t version, std::chrono::milliseconds timeout) {
  std::unique_lock lock(stateMutex_);
  changed_.wait_for(lock, timeout, [&] { return stopping_ || state_.version != version; });
  return state_;
}

void ViewSession::shutdown() {
  {
    std::lock_guard lock(stateMutex_);
    stopping_ = true;
    if (outdated_) *outdated_ = true;
  }
  changed_.notify_all();
  std::lock_guard lock(cancelMutex_);
  if (cancelCurrent_) *cancelCurrent_ = true;
}

std::shared_ptr<const Scene> ViewSession::currentScene() const {
  std::lock_guard lock(stateMutex_);
  if (!state_.scene) throw std::runtime_error(state_.error.empty() ? "no scene yet" : state_.error);
  return state_.scene;
}

std::string ViewSession::frame(const FrameRequest& request) {
  // The render in progress stops at its next pixel: its page has moved on.
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  {
    std::lock_guard lock(cancelMutex_);
    if (cancelCurrent_) *cancelCurrent_ = true;
    cancelCurrent_ = cancel;
  }
  std::lock_guard rendering(renderMutex_);
  if (*cancel) throw RenderCancelled();
  Scene scene = *currentScene();
  request.applyTo(scene);
  RenderOptions options(request.passWidth(), request.passHeight());
  options.threadPool = &threads_;
  options.samples = request.samples();
  options.adaptive = options.samples > 1;
  options.cancel = cancel.get();
  options.section = request.section;
  threads_.wake();
  const Image image = Renderer(scene, options).render();
  return encodePng(image.width, image.height,
                   pngRows(image.rgb.data(), image.width, ImageData::LinearColor), threads_.size());
}

PickResult ViewSession::pick(const FrameRequest& request, double x, double y) {
  if (!(x >= 0.0 && y >= 0.0 && x <= request.width && y <= request.height))
    throw std::invalid_argument("x and y must be within the frame's size");
  std::lock_guard rendering(renderMutex_);
  Scene scene = *currentScene();
  request.applyTo(scene);
  RenderOptions options(request.width, request.height);
  options.section = request.section;
  const Renderer renderer(scene, options);
  const Camera camera(renderer.camera(), request.width, request.height);
  const Ray ray = camera.ray(x, y);
  PickResult result;
  const std::optional<SurfaceHit> hit = renderer.firstHit(ray);
  if (!hit) return result;
  result.hit = true;
  result.point = ray.origin + hit->t * ray.dir;
  if (const Primitive* primitive = hit->boundary.primitive) {
    result.kind = primitive->material() == sectionMaterial() ? "section" : primitive->kind();
    result.source = primitive->origin().text();
    result.normal = renderer.normalAt(*hit, ray);
    if (hit->boundary.flip) result.normal = -result.normal;
  } else if (hit->surface) {
    result.kind = hit->surface->kind();
    // An open surface has two sides: the normal of the one seen (0 − n, not
    // −n, so that no component is −0).
    result.normal = hit->surface->normalAt(result.point, hit->face);
    if (glm::dot(result.normal, ray.dir) > 0.0) result.normal = dvec3(0.0) - result.normal;
  }
  return result;
}

}  // namespace csgray::detail
