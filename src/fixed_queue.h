// A first-in first-out queue of at most `capacity` values that never allocates after its
// construction: a ring over a vector, for hot paths that queue a bounded set of items
// (AsyncEnvironmentPool's worlds: each is at most once in each queue).
#pragma once

#include <vector>

namespace colav {

template <typename T>
class FixedQueue {
 public:
  explicit FixedQueue(int capacity) : values_(capacity) {}
  int size() const { return size_; }
  /// The k-th value from the front (0 <= k < capacity; unchecked).
  T& operator[](int k) {
    const int index = head_ + k;  // no modulo: a division costs more than the rest of a push
    return values_[index < capacity() ? index : index - capacity()];
  }
  /// Appends `value`; the queue must not be full (unchecked).
  void Push(const T& value) { (*this)[size_++] = value; }
  /// Removes the k-th value; those before it keep their order.
  T Remove(int k) {
    const T value = (*this)[k];
    for (; k > 0; --k) (*this)[k] = (*this)[k - 1];
    head_ = head_ + 1 < capacity() ? head_ + 1 : 0;
    --size_;
    return value;
  }
  T Pop() { return Remove(0); }
  void Clear() { size_ = 0; }

 private:
  int capacity() const { return static_cast<int>(values_.size()); }

  std::vector<T> values_;
  int head_ = 0;
  int size_ = 0;
};

}  // namespace colav
