#include "view/file_watcher.h"

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace csgray::detail {

namespace {

constexpr std::uint32_t kEvents =
    IN_CLOSE_WRITE | IN_MODIFY | IN_CREATE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM;

}  // namespace

FileWatcher::FileWatcher(std::function<void()> changed, std::chrono::milliseconds debounce)
    : changed_(std::move(changed)), debounce_(debounce) {
  inotify_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  wake_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (inotify_ < 0 || wake_ < 0) {
    const std::string reason = std::strerror(errno);
    if (inotify_ >= 0) close(inotify_);
    if (wake_ >= 0) close(wake_);
    throw std::runtime_error("cannot watch files: " + reason);
  }
  thread_ = std::thread([this] { loop(); });
}

FileWatcher::~FileWatcher() {
  const std::uint64_t one = 1;
  if (write(wake_, &one, sizeof one) < 0) {
    // The loop polls this descriptor; a full counter wakes it as well.
  }
  thread_.join();
  close(inotify_);
  close(wake_);
}

void FileWatcher::watch(const std::vector<std::string>& files) {
  std::map<std::string, std::set<std::string>> names;
  for (const std::string& file : files) {
    std::filesystem::path path = std::filesystem::absolute(file).lexically_normal();
    names[path.parent_path().string()].insert(path.filename().string());
  }
  std::lock_guard lock(mutex_);
  for (auto it = folders_.begin(); it != folders_.end();)
    if (!names.count(it->second)) {
      inotify_rm_watch(inotify_, it->first);
      it = folders_.erase(it);
    } else {
      ++it;
    }
  for (const auto& [folder, _] : names) {
    // Adding a watch twice returns the same descriptor.
    const int wd = inotify_add_watch(inotify_, folder.c_str(), kEvents);
    if (wd >= 0) folders_[wd] = folder;
  }
  names_ = std::move(names);
}

void FileWatcher::loop() {
  using Clock = std::chrono::steady_clock;
  bool pending = false;
  Clock::time_point due;
  alignas(inotify_event) char buffer[16 * 1024];
  while (true) {
    int timeout = -1;
    if (pending) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(due - Clock::now());
      timeout = int(std::max<long long>(left.count(), 0));
    }
    pollfd fds[2] = {{inotify_, POLLIN, 0}, {wake_, POLLIN, 0}};
    const int ready = poll(fds, 2, timeout);
    if (ready < 0 && errno != EINTR) return;
    if (fds[1].revents) return;
    if (ready > 0 && (fds[0].revents & POLLIN)) {
      ssize_t length;
      while ((length = read(inotify_, buffer, sizeof buffer)) > 0) {
        std::lock_guard lock(mutex_);
        for (char* p = buffer; p < buffer + length;) {
          const auto* event = reinterpret_cast<const inotify_event*>(p);
          p += sizeof(inotify_event) + event->len;
          auto folder = folders_.find(event->wd);
          if (folder == folders_.end() || event->len == 0) continue;
          auto names = names_.find(folder->second);
          if (names != names_.end() && names->second.count(event->name)) {
            pending = true;
            due = Clock::now() + debounce_;
          }
        }
      }
      continue;
    }
    if (pending && Clock::now() >= due) {
      pending = false;
      changed_();
    }
  }
}

}  // namespace csgray::detail
