// The page's export and check buttons: the work runs on the server, on a
// thread of its own, one job at a time, while frames go on rendering; the
// page polls its stage and fetches the result (the file's bytes, served as
// a download, never written into the user's folder; or the check's report).
// A job belongs to the version of the part it started on: once the script
// runs again, its result is stale (view_routes.cpp refuses to serve it),
// and the job stops at its next step (the version's `outdated` flag).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "check/check_report.h"
#include "scene/scene.h"

namespace csgray::detail {

// What a job runs, given by the command line, which has the mesh tools
// (meshio/part_file_bytes.h and check/part_check.h, in a module of their
// own).
struct PartTools {
  // The part's mesh file ("stl" or "3mf") as bytes; tells stage() where it is.
  std::function<std::string(const Scene& scene, const std::string& script,
                            const std::string& format,
                            const std::function<void(const std::string& stage)>& stage)>
      meshFile;
  std::function<CheckReport(const Scene& scene, const std::string& script)> check;
};

struct JobStatus {
  std::uint64_t id = 0;  // 0: no job yet
  std::string kind;      // "export" or "check"
  std::string format;    // of an export: "stl" or "3mf"
  // "mesh", "write" (an export), "check", then "done", "failed", or
  // "stopped" (the part changed while it ran, or the server stopped).
  std::string stage;
  bool running = false;
  std::string error;          // one line, when failed
  std::uint64_t version = 0;  // of the part it ran on
  std::size_t bytes = 0;      // of the exported file
  std::optional<CheckReport> report;
};

// A job asked for while another runs.
class JobBusy : public std::runtime_error {
 public:
  explicit JobBusy(const std::string& kind)
      : std::runtime_error("a" + std::string(kind == "export" ? "n " : " ") + kind +
                           " is running; wait for it to end") {}
};

class ViewJobs {
 public:
  explicit ViewJobs(PartTools tools) : tools_(std::move(tools)) {}
  ~ViewJobs();  // waits for the job in progress (the session's shutdown stops it)
  ViewJobs(const ViewJobs&) = delete;
  ViewJobs& operator=(const ViewJobs&) = delete;

  // Start a job on the scene of that version; return its id. The job
  // stops once `outdated` is set (SessionState::outdated). Throw JobBusy
  // while one runs, std::invalid_argument for a format other than stl and 3mf.
  std::uint64_t startExport(std::shared_ptr<const Scene> scene, std::uint64_t version,
                            std::shared_ptr<const std::atomic<bool>> outdated,
                            const std::string& script, const std::string& format);
  std::uint64_t startCheck(std::shared_ptr<const Scene> scene, std::uint64_t version,
                           std::shared_ptr<const std::atomic<bool>> outdated,
                           const std::string& script);

  JobStatus status() const;
  // The file of export `id`, when it is the last job and it is done.
  std::optional<std::string> file(std::uint64_t id) const;
  // Waits until no job runs (the tests).
  void waitIdle() const;

 private:
  std::uint64_t start(const std::string& kind, const std::string& format, std::uint64_t version,
                      std::shared_ptr<const std::atomic<bool>> outdated,
                      std::function<void()> work);
  void setStage(const std::string& stage);

  const PartTools tools_;
  mutable std::mutex mutex_;
  mutable std::condition_variable idle_;
  JobStatus status_;
  std::string file_;
  std::thread worker_;
};

}  // namespace csgray::detail
