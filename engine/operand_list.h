// The operands of a boolean node, in storage that a chain of nodes can
// share. A script that drills holes one at a time (s = s - hole, in a
// loop) makes a node per hole, each with every hole so far: copied into
// each node, n holes cost n²/2 copies (40 000 holes: 800 million, 22 s).
// Here a node that extends another's list by a few operands writes them
// into the room left after that list, where no node has written yet, and
// shares the storage; only when the room runs out (or another node has
// already extended the same list) are the operands copied, into storage
// with room for as many again. So a chain of n costs O(n), and a list
// once made never changes: a node reads its first size() operands only,
// and nothing is written there again, on any thread.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "engine/solid.h"

namespace csgray::detail {

class OperandList {
 public:
  OperandList() = default;
  // These operands, in storage of their own.
  explicit OperandList(const std::vector<SolidPtr>& operands);
  // base's operands followed by more.
  static OperandList extended(const OperandList& base, std::span<const SolidPtr> more);

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const SolidPtr& operator[](std::size_t i) const { return data_[i]; }
  const SolidPtr* begin() const { return data_; }
  const SolidPtr* end() const { return data_ + size_; }
  std::span<const SolidPtr> span() const { return {data_, size_}; }
  // The storage, which lists may share, and what it takes: for a count of
  // memory that counts each storage once, while it lives.
  std::shared_ptr<const void> storage() const { return store_; }
  std::size_t storageBytes() const {
    return store_ ? sizeof(Store) + store_->capacity * sizeof(SolidPtr) : 0;
  }

 private:
  struct Store {
    explicit Store(std::size_t capacity)
        : slots(std::make_unique<SolidPtr[]>(capacity)), capacity(capacity) {}
    std::unique_ptr<SolidPtr[]> slots;
    std::size_t capacity;
    std::atomic<std::size_t> used{0};  // slots written by some list
  };

  // A list of base's operands and more, in new storage of that capacity.
  static OperandList copied(std::span<const SolidPtr> base, std::span<const SolidPtr> more,
                            std::size_t capacity);

  std::shared_ptr<Store> store_;
  const SolidPtr* data_ = nullptr;  // store_'s slots (one load for a ray's walk, not two)
  std::size_t size_ = 0;
};

}  // namespace csgray::detail
