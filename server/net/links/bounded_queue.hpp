// BoundedQueue: a small thread-safe FIFO between the simulation thread and the network side.
// When full, the oldest item is dropped: for a live stream the newest tick is the one that matters.
#pragma once

#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

namespace ocean::server {

template <typename T>
class BoundedQueue {
 public:
  explicit BoundedQueue(std::size_t capacity) : capacity_(capacity < 1 ? 1 : capacity) {}

  struct PushResult {
    bool was_empty = false;  // the consumer may need waking
    bool dropped = false;    // the oldest item was discarded to make room
  };

  PushResult push(T item) {
    std::lock_guard lock(mutex_);
    PushResult result{items_.empty(), false};
    if (items_.size() == capacity_) {
      items_.pop_front();
      result.dropped = true;
    }
    items_.push_back(std::move(item));
    return result;
  }

  std::optional<T> pop() {
    std::lock_guard lock(mutex_);
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    return item;
  }

  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return items_.size();
  }

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::deque<T> items_;
};

}  // namespace ocean::server
