// What `csgray view` holds between requests: the script, its customizer
// values, the last scene it made that rendered (kept while the script is
// broken, so the page keeps its image), the error of the last run, and the
// files the script read, to watch. The frames and picks of view_frame.h
// render from it; one render at a time, and a newer frame cancels the one
// in progress.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "raytrace/render_threads.h"
#include "scene/scene.h"
#include "script/script.h"

namespace csgray::detail {

struct FrameRequest;
struct PickResult;

// What a run of the script left, as the page shows it.
struct SessionState {
  // Bumped by every run of the script, good or bad.
  std::uint64_t version = 0;
  std::shared_ptr<const Scene> scene;  // the last good one; null before any
  std::string error;                   // of the last run; empty when it was good
  std::vector<Parameter> parameters;   // the last good annotations
  // The customizer's values that differ from the script's (as -D texts).
  std::vector<std::pair<std::string, std::string>> defines;
  std::vector<std::string> files;  // the script and the files it read
  double volume = 0.0;             // of the scene's solids, exactVolume; 0 if unbounded
  Bounds bounds;                   // of the scene's solids, Scene::partBounds
  // Set once the script runs again, or the server stops: work on this
  // version (an export, a check: view_jobs.h) reads it to stop, its
  // result no longer wanted (engine/cancellation.h).
  std::shared_ptr<const std::atomic<bool>> outdated;
};

class ViewSession {
 public:
  // Runs a script with options: runScriptFile, or the command line's
  // wrapping of it in its time limit.
  using ScriptRunner = std::function<Scene(const std::string& path, const ScriptOptions& options)>;

  // options: as the command line makes them (its -D are the customizer's
  // first values); threads: 0 for one per core; runner: runScriptFile
  // where empty. Runs the script once.
  ViewSession(std::string script, ScriptOptions options, int threads = 0, ScriptRunner runner = {});
  ~ViewSession();
  ViewSession(const ViewSession&) = delete;
  ViewSession& operator=(const ViewSession&) = delete;

  const std::string& script() const { return script_; }

  // Runs the script again (its file changed, say), keeping the scene it
  // made last when this run fails.
  void reload();
  // Sets a customizer value (value: a -D text), or drops it (nullopt: the
  // script's default), and runs the script. Returns the -D's refusal
  // ("-D width=500: width must be from 10 to 100 (part.lua:3)"), when the
  // value is not kept, or "".
  std::string define(const std::string& name, const std::optional<std::string>& value);

  SessionState state() const;
  // Waits until the version is no longer `version`, up to timeout, or
  // until shutdown(); returns the state then.
  SessionState waitForChange(std::uint64_t version, std::chrono::milliseconds timeout);
  // Ends every wait (the server is stopping).
  void shutdown();

  // A PNG of the last good scene as the request says. Throws
  // RenderCancelled when a newer frame came meanwhile, std::invalid_argument
  // for a request the scene cannot take (nothing to show, a camera inside
  // out), std::runtime_error when there is no scene yet.
  std::string frame(const FrameRequest& request);
  // What lies under pixel (x, y) of a frame of that request.
  PickResult pick(const FrameRequest& request, double x, double y);

 private:
  // Runs the script with these defines; on success installs the scene.
  // Returns the DefineError's message when a define is refused.
  std::string run(const std::vector<std::pair<std::string, std::string>>& defines);
  std::shared_ptr<const Scene> currentScene() const;
  // A new version: the one before is outdated. With stateMutex_ held.
  void nextVersion();

  const std::string script_;
  const ScriptOptions options_;
  const ScriptRunner runner_;
  std::mutex runMutex_;  // one run of the script at a time
  mutable std::mutex stateMutex_;
  std::condition_variable changed_;
  SessionState state_;
  std::shared_ptr<std::atomic<bool>> outdated_;  // state_.outdated, to set
  bool stopping_ = false;

  RenderThreads threads_;
  std::mutex renderMutex_;  // one render at a time
  std::mutex cancelMutex_;
  std::shared_ptr<std::atomic<bool>> cancelCurrent_;  // the render in progress's flag
};

}  // namespace csgray::detail
