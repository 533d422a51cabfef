#pragma once
// A vector with inline, fixed capacity: the solve path keeps its constraint sets in these so a
// solve never touches the heap. push_back beyond capacity is refused (returns false) so callers
// can turn overflow into an `unhandled` answer instead of a crash.
#include <array>
#include <cassert>
#include <cstddef>

namespace relpos {

template <typename T, std::size_t N>
class FixedVector {
 public:
  static constexpr std::size_t kCapacity = N;
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == N; }
  void clear() { size_ = 0; }
  bool push_back(const T& v) {
    if (size_ == N) return false;
    data_[size_++] = v;
    return true;
  }
  void erase(std::size_t i) {
    assert(i < size_);
    for (std::size_t k = i + 1; k < size_; ++k) data_[k - 1] = data_[k];
    --size_;
  }
  T& operator[](std::size_t i) {
    assert(i < size_);
    return data_[i];
  }
  const T& operator[](std::size_t i) const {
    assert(i < size_);
    return data_[i];
  }
  T* begin() { return data_.data(); }
  T* end() { return data_.data() + size_; }
  const T* begin() const { return data_.data(); }
  const T* end() const { return data_.data() + size_; }

 private:
  std::array<T, N> data_{};
  std::size_t size_ = 0;
};

}  // namespace relpos
