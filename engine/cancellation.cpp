#include "engine/cancellation.h"

namespace csgray::detail {

namespace {
thread_local const std::atomic<bool>* current = nullptr;
}  // namespace

CancelScope::CancelScope(const std::atomic<bool>* flag) : outer_(current) { current = flag; }

CancelScope::~CancelScope() { current = outer_; }

const std::atomic<bool>* cancelFlag() { return current; }

}  // namespace csgray::detail
