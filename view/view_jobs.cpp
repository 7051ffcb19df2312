#include "view/view_jobs.h"

#include "engine/cancellation.h"

namespace csgray::detail {

ViewJobs::~ViewJobs() {
  if (worker_.joinable()) worker_.join();
}

std::uint64_t ViewJobs::start(const std::string& kind, const std::string& format,
                              std::uint64_t version,
                              std::shared_ptr<const std::atomic<bool>> outdated,
                              std::function<void()> work) {
  std::lock_guard lock(mutex_);
  if (status_.running) throw JobBusy(status_.kind);
  if (worker_.joinable()) worker_.join();  // ended: its thread is done
  const std::uint64_t id = status_.id + 1;
  status_ = JobStatus{};
  status_.id = id;
  status_.kind = kind;
  status_.format = format;
  status_.stage = kind == "check" ? "check" : "mesh";
  status_.running = true;
  status_.version = version;
  file_.clear();
  worker_ = std::thread([this, outdated = std::move(outdated), work = std::move(work)] {
    std::string error;
    bool stopped = false;
    try {
      const CancelScope scope(outdated.get());
      work();
    } catch (const Cancelled&) {
      stopped = true;
    } catch (const std::exception& e) {
      error = e.what();
    } catch (...) {
      error = "the job failed";
    }
    std::lock_guard done(mutex_);
    status_.running = false;
    status_.error = error;
    status_.stage = stopped ? "stopped" : error.empty() ? "done" : "failed";
    if (stopped || !error.empty()) file_.clear();
    status_.bytes = file_.size();
    idle_.notify_all();
  });
  return id;
}

void ViewJobs::setStage(const std::string& stage) {
  std::lock_guard lock(mutex_);
  status_.stage = stage;
}

std::uint64_t ViewJobs::startExport(std::shared_ptr<const Scene> scene, std::uint64_t version,
                                    std::shared_ptr<const std::atomic<bool>> outdated,
                                    const std::string& script, const std::string& format) {
  if (format != "stl" && format != "3mf") throw std::invalid_argument("format must be stl or 3mf");
  if (!tools_.meshFile) throw std::invalid_argument("export is not available here");
  return start("export", format, version, std::move(outdated), [this, scene, script, format] {
    std::string bytes =
        tools_.meshFile(*scene, script, format, [this](const std::string& s) { setStage(s); });
    std::lock_guard lock(mutex_);
    file_ = std::move(bytes);
  });
}

std::uint64_t ViewJobs::startCheck(std::shared_ptr<const Scene> scene, std::uint64_t version,
                                   std::shared_ptr<const std::atomic<bool>> outdated,
                                   const std::string& script) {
  if (!tools_.check) throw std::invalid_argument("the check is not available here");
  return start("check", "", version, std::move(outdated), [this, scene, script] {
    CheckReport report = tools_.check(*scene, script);
    std::lock_guard lock(mutex_);
    status_.report = std::move(report);
  });
}

JobStatus ViewJobs::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

std::optional<std::string> ViewJobs::file(std::uint64_t id) const {
  std::lock_guard lock(mutex_);
  if (id != status_.id || status_.kind != "export" || status_.stage != "done") return std::nullopt;
  return file_;
}

void ViewJobs::waitIdle() const {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [&] { return !status_.running; });
}

}  // namespace csgray::detail
