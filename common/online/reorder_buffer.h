// ReorderBuffer: puts data arriving with different latencies back in time order. A datum is
// released once the newest time seen is `lag` past it; one older than what was already released
// is refused (the caller counts and drops it), never reordered into the past.
#pragma once

#include <cmath>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace giocal {

template <class T>
class ReorderBuffer {
 public:
  explicit ReorderBuffer(double lag) : lag_(lag) {}

  /// False (and nothing stored) when t is before the released frontier or not finite.
  bool push(double t, T item) {
    if (!std::isfinite(t) || t < released_t_) return false;
    heap_.push({t, seq_++, std::move(item)});
    newest_ = std::max(newest_, t);
    return true;
  }
  /// Hands out, in time order (ties in arrival order), everything at least `lag` old; with
  /// `all`, everything.
  void release(const std::function<void(double, T&)>& out, bool all = false) {
    while (!heap_.empty() && (all || heap_.top().t <= newest_ - lag_)) {
      Entry e = std::move(const_cast<Entry&>(heap_.top()));
      heap_.pop();
      released_t_ = e.t;
      out(e.t, e.item);
    }
  }
  size_t size() const { return heap_.size(); }
  double newest() const { return newest_; }

 private:
  struct Entry {
    double t;
    long seq;
    T item;
    bool operator<(const Entry& o) const {  // std::priority_queue keeps the largest on top
      return t != o.t ? t > o.t : seq > o.seq;
    }
  };
  double lag_;
  double newest_ = -INFINITY, released_t_ = -INFINITY;
  long seq_ = 0;
  std::priority_queue<Entry> heap_;
};

}  // namespace giocal
