#include "script/held_objects.h"

namespace csgray::detail {

namespace {
// Do two pointers share ownership of one object?
bool sameOwner(const std::weak_ptr<const void>& a, const std::shared_ptr<const void>& b) {
  return !a.owner_before(b) && !b.owner_before(a);
}
}  // namespace

bool HeldObjects::counts(const std::shared_ptr<const void>& object) const {
  auto it = entries_.find(object.get());
  return it != entries_.end() && sameOwner(it->second.object, object);
}

bool HeldObjects::add(const std::shared_ptr<const void>& object, std::size_t bytes) {
  auto [it, inserted] = entries_.try_emplace(object.get(), Entry{object, bytes});
  if (inserted) return true;
  if (sameOwner(it->second.object, object) && !it->second.object.expired()) return false;
  // The address of an object that has died (an object made apart from its
  // control block frees its memory while a weak pointer remains).
  replaced_ += it->second.bytes;
  it->second = Entry{object, bytes};
  return true;
}

std::size_t HeldObjects::sweep() {
  std::size_t freed = replaced_;
  replaced_ = 0;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.object.expired()) {
      freed += it->second.bytes;
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
  sizeAfterSweep_ = entries_.size();
  return freed;
}

}  // namespace csgray::detail
