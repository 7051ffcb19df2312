// Calls back when any of a set of files changes, after a quiet spell
// (debounce): an editor's save is often several writes, or a new file
// renamed over the old one (vim, most IDEs), or the old one deleted and a
// new one made. So the folders are watched (inotify(7)), not the files,
// and an event counts when it names a watched file: it is written and
// closed, made, moved there, deleted, or moved away.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace csgray::detail {

class FileWatcher {
 public:
  // changed runs on the watcher's own thread, once per burst of events,
  // debounce after the last; not again until it has returned.
  explicit FileWatcher(std::function<void()> changed,
                       std::chrono::milliseconds debounce = std::chrono::milliseconds(100));
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Watches these files from now on, in place of those before. A folder
  // that cannot be watched (gone, not readable) is left out.
  void watch(const std::vector<std::string>& files);

 private:
  void loop();

  std::function<void()> changed_;
  std::chrono::milliseconds debounce_;
  int inotify_ = -1;
  int wake_ = -1;  // an eventfd that ends the loop
  std::mutex mutex_;
  std::map<int, std::string> folders_;                  // watch descriptor → folder
  std::map<std::string, std::set<std::string>> names_;  // folder → file names in it
  std::thread thread_;
};

}  // namespace csgray::detail
