#include "engine/operand_list.h"

#include <algorithm>

namespace csgray::detail {

OperandList::OperandList(const std::vector<SolidPtr>& operands)
    : OperandList(copied({}, operands, operands.size())) {}

OperandList OperandList::copied(std::span<const SolidPtr> base, std::span<const SolidPtr> more,
                                std::size_t capacity) {
  OperandList list;
  list.store_ = std::make_shared<Store>(capacity);
  SolidPtr* out = std::copy(base.begin(), base.end(), list.store_->slots.get());
  std::copy(more.begin(), more.end(), out);
  list.data_ = list.store_->slots.get();
  list.size_ = base.size() + more.size();
  list.store_->used.store(list.size_, std::memory_order_relaxed);
  return list;
}

OperandList OperandList::extended(const OperandList& base, std::span<const SolidPtr> more) {
  const std::size_t size = base.size_ + more.size();
  if (base.store_ && size <= base.store_->capacity) {
    // Claim the room after base's operands, unless some list has taken it.
    std::size_t expected = base.size_;
    if (base.store_->used.compare_exchange_strong(expected, size)) {
      std::copy(more.begin(), more.end(), base.store_->slots.get() + base.size_);
      OperandList list;
      list.store_ = base.store_;
      list.data_ = base.data_;
      list.size_ = size;
      return list;
    }
  }
  return copied(base.span(), more, std::max<std::size_t>(2 * size, 8));
}

}  // namespace csgray::detail
