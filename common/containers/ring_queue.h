// RingQueue: a first-in first-out queue in one growing array used as a ring, so that a queue
// that holds a bounded number of items allocates nothing once it has grown to that number
// (std::deque frees and allocates a block each time its ends cross one: every push of a large
// item). Items can also be inserted in the middle (the reorder buffer's late data).
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace giocal {

template <class T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  /// The i-th item from the front.
  T& operator[](std::size_t i) { return slots_[(head_ + i) & (slots_.size() - 1)]; }
  const T& operator[](std::size_t i) const { return slots_[(head_ + i) & (slots_.size() - 1)]; }
  T& front() { return (*this)[0]; }
  const T& front() const { return (*this)[0]; }
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }

  void push_back(T item) { insert(size_, std::move(item)); }
  /// Inserts before the item now at `index` (index == size(): at the back), moving the items
  /// behind it one place back.
  void insert(std::size_t index, T item) {
    if (size_ == slots_.size()) grow();
    for (std::size_t k = size_; k > index; --k) (*this)[k] = std::move((*this)[k - 1]);
    (*this)[index] = std::move(item);
    ++size_;
  }
  void pop_front() {
    // What the item held (an epoch's vectors) is freed now, as std::deque does.
    if constexpr (!std::is_trivially_destructible_v<T>) front() = T();
    head_ = (head_ + 1) & (slots_.size() - 1);
    --size_;
  }
  void clear() {
    while (!empty()) pop_front();
    head_ = 0;
  }

 private:
  void grow() {  // the capacity stays a power of two: an index wraps with a mask
    std::vector<T> bigger(slots_.empty() ? 16 : 2 * slots_.size());
    for (std::size_t k = 0; k < size_; ++k) bigger[k] = std::move((*this)[k]);
    slots_.swap(bigger);
    head_ = 0;
  }

  std::vector<T> slots_;
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace giocal
