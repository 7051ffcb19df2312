// The C++ objects that a script's values hold (the nodes of solids,
// surfaces, textures), each counted once from when a value first holds it
// until it is destroyed. Counting per Lua value and refunding when Lua
// collects the value undercounts: the nodes of a collected value live on
// wherever another value shares them (the copy that s:translate() makes,
// spliced into the union s + s:translate()). So an object is known by a
// weak pointer, and counted until that pointer expires.
#pragma once

#include <cstddef>
#include <memory>
#include <unordered_map>

namespace csgray::detail {

// What the objects cost, with the shared pointer's control block and the
// allocator's overhead (tests/script/sandbox_test.cpp holds them against
// the sizes of the types).
inline constexpr std::size_t kBytesPerShape =
    1024;  // a primitive with its frames, a surface, a texture
inline constexpr std::size_t kBytesPerBoolean = 512;  // a boolean node, besides its operand list

class HeldObjects {
 public:
  // What one entry of this table costs, besides the object it counts.
  static constexpr std::size_t kEntryBytes = 96;

  // Is the object counted (and alive)?
  bool counts(const std::shared_ptr<const void>& object) const;
  // Counts the object for bytes; false if it is counted already.
  bool add(const std::shared_ptr<const void>& object, std::size_t bytes);
  // Forgets the objects that have been destroyed, and returns the bytes
  // they were counted for.
  std::size_t sweep();
  // Is a sweep due? When the table has doubled since the last one, so that
  // sweeping costs a constant time per object counted.
  bool sweepDue() const { return entries_.size() >= 2 * sizeAfterSweep_ + 4096; }

 private:
  struct Entry {
    std::weak_ptr<const void> object;
    std::size_t bytes;
  };
  std::unordered_map<const void*, Entry> entries_;
  std::size_t sizeAfterSweep_ = 0;
  // An entry whose object died and whose address a new object took, set
  // aside by add() until the next sweep refunds it.
  std::size_t replaced_ = 0;
};

}  // namespace csgray::detail
