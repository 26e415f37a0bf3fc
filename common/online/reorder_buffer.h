// ReorderBuffer: puts data arriving with different latencies back in time order. A datum is
// released once the newest time seen is `lag` past it; one older than what was already released
// is refused (the caller counts and drops it), never reordered into the past.
#pragma once

#include <cmath>
#include <functional>
#include <utility>

#include "common/containers/ring_queue.h"

namespace giocal {

template <class T>
class ReorderBuffer {
 public:
  explicit ReorderBuffer(double lag) : lag_(lag) {}

  /// False (and nothing stored) when t is before the released frontier or not finite.
  bool push(double t, T item) {
    if (!std::isfinite(t) || t < released_t_) return false;
    // Kept sorted, inserted after every entry at or before t (ties stay in arrival order). Data
    // mostly arrive in order, so the search from the back ends at once; a heap moved the large
    // data a log(n) times per datum.
    std::size_t at = items_.size();
    while (at > 0 && items_[at - 1].first > t) --at;
    items_.insert(at, {t, std::move(item)});
    newest_ = std::max(newest_, t);
    return true;
  }
  /// Hands out, in time order (ties in arrival order), everything at least `lag` old; with
  /// `all`, everything.
  void release(const std::function<void(double, T&)>& out, bool all = false) {
    while (!items_.empty() && (all || items_.front().first <= newest_ - lag_)) {
      std::pair<double, T> e = std::move(items_.front());
      items_.pop_front();
      released_t_ = e.first;
      out(e.first, e.second);
    }
  }
  size_t size() const { return items_.size(); }
  double newest() const { return newest_; }

 private:
  double lag_;
  double newest_ = -INFINITY, released_t_ = -INFINITY;
  RingQueue<std::pair<double, T>> items_;  // in time order
};

}  // namespace giocal
