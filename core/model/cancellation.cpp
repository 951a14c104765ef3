#include "core/model/cancellation.hpp"

#include <atomic>

namespace orni {

namespace {
std::atomic<bool> g_cancel_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler must be able to set it");
}  // namespace

void requestCancellation() noexcept { g_cancel_requested.store(true, std::memory_order_relaxed); }
void clearCancellation() noexcept { g_cancel_requested.store(false, std::memory_order_relaxed); }
bool cancellationRequested() noexcept {
  return g_cancel_requested.load(std::memory_order_relaxed);
}

}  // namespace orni
