#pragma once
// Items that finish out of order (worker threads) handed on in their order as early as possible.

#include <cstddef>
#include <functional>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace rollcontact::batch {

/// Hands items 0, 1, 2, … to `consume` in that order while they arrive in any order: item k is
/// handed on as soon as every item before it has been, so that only the items waiting for an
/// earlier one are held (a threaded run's case outputs: at most about one per worker sequence,
/// not all of them until the end). Thread-safe; `consume` runs under the lock, one item at a
/// time, on the thread whose add() completed the order.
template <class T>
class InOrder {
 public:
  explicit InOrder(std::function<void(std::size_t index, T& item)> consume)
      : consume_(std::move(consume)) {}

  /// Item k (each index exactly once; std::logic_error otherwise).
  void add(std::size_t k, T item) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (k < next_ || waiting_.contains(k))
      throw std::logic_error("InOrder: item " + std::to_string(k) + " added twice");
    waiting_.emplace(k, std::move(item));
    for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_;
         it = waiting_.erase(it), ++next_)
      consume_(it->first, it->second);
  }

  /// Items handed on so far (every index below this one).
  std::size_t handed_on() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return next_;
  }
  /// Items held until an earlier one arrives.
  std::size_t waiting() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return waiting_.size();
  }

 private:
  std::function<void(std::size_t, T&)> consume_;
  mutable std::mutex mutex_;
  std::map<std::size_t, T> waiting_;
  std::size_t next_ = 0;
};

}  // namespace rollcontact::batch
