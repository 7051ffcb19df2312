#include "view/view_app.h"

#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>

#include "view/file_watcher.h"
#include "view/view_routes.h"
#include "view/view_session.h"

extern char** environ;

namespace csgray::detail {

namespace {

// The page in the user's browser, by xdg-open; a note when there is none.
void openBrowser(const std::string& url) {
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  pid_t pid;
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) !=
      0) {
    std::fprintf(stderr, "csgray: cannot start xdg-open; open %s in a browser\n", url.c_str());
    return;
  }
  // xdg-open returns once the browser has it; not waited for, it would
  // stay a zombie until then.
  std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();
}

// A line on standard error if the work it is held over takes longer than
// `seconds` (a slow script's first run, before the page can be served), so
// that the terminal is not silent meanwhile.
class NoticeIfSlow {
 public:
  NoticeIfSlow(std::string line, double seconds)
      : thread_([this, seconds, line = std::move(line)] {
          std::unique_lock lock(mutex_);
          // No time at all: said whatever the work did meanwhile (else a
          // quick run could finish before this thread looked).
          if (seconds <= 0.0 || !done_.wait_for(lock, std::chrono::duration<double>(seconds),
                                                [this] { return finished_; }))
            std::fprintf(stderr, "%s\n", line.c_str());
        }) {}
  ~NoticeIfSlow() {
    {
      std::lock_guard lock(mutex_);
      finished_ = true;
    }
    done_.notify_one();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_;
  bool finished_ = false;
  std::thread thread_;
};

std::unique_ptr<ViewSession> firstRun(const ViewOptions& options) {
  NoticeIfSlow notice("csgray: running " + options.script + "; the page is served once it has run",
                      options.slowRunSeconds);
  return std::make_unique<ViewSession>(options.script, options.scriptOptions, options.threads,
                                       options.runScript);
}

}  // namespace

int serveView(const ViewOptions& options) {
  const std::unique_ptr<ViewSession> first = firstRun(options);
  ViewSession& session = *first;
  FileWatcher watcher([&] {
    session.reload();
    watcher.watch(session.state().files);
  });
  watcher.watch(session.state().files);
  ViewJobs jobs(options.tools);
  ViewRoutes routes(session, &jobs);
  const std::unique_ptr<HttpServer> server =
      options.makeServer(routes, options.address, options.port);
  if (!isLoopback(options.address))
    std::fprintf(stderr,
                 "csgray: warning: listening on %s: other machines on the network, and web "
                 "pages open on this one, can see this part and set its parameters\n",
                 options.address.c_str());
  // The page shows the script's error too, and the part once it is fixed
  // and saved; the terminal says so at once (a misspelt file name).
  if (const std::string error = session.state().error; !error.empty())
    std::fprintf(stderr, "csgray: warning: %s; the page shows the part once it is saved\n",
                 error.c_str());
  std::printf("csgray: viewing %s at %s (Ctrl-C to stop)\n", options.script.c_str(),
              server->url().c_str());
  std::fflush(stdout);
  if (options.open) openBrowser(server->url());
  server->run();
  return 0;
}

}  // namespace csgray::detail
