#pragma once
// A vector with inline, fixed capacity: the solve path keeps its constraint sets in these so a
// solve never touches the heap. push_back beyond capacity is refused (returns false) so callers
// can turn overflow into an `unhandled` answer instead of a crash.
//
// The slots are raw storage: an empty vector costs nothing to create, and copying one copies its
// elements only, not its capacity (a constraint set holds 48 fundamentals' worth of slots and is
// copied on every branch; copying the whole capacity was a fifth of a solve).
#include <cassert>
#include <cstddef>
#include <new>
#include <type_traits>

namespace relpos {

template <typename T, std::size_t N>
class FixedVector {
 public:
  static constexpr std::size_t kCapacity = N;
  // User-provided (not `= default`): value-initialising one — `{}`, emplace_back() — would
  // otherwise zero all N slots first.
  FixedVector() noexcept {}  // NOLINT(modernize-use-equals-default)
  FixedVector(const FixedVector& o) { copyFrom(o); }
  FixedVector& operator=(const FixedVector& o) {
    if (this != &o) {
      clear();
      copyFrom(o);
    }
    return *this;
  }
  ~FixedVector() { clear(); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == N; }
  void clear() {
    if constexpr (!std::is_trivially_destructible_v<T>)
      for (std::size_t i = 0; i < size_; ++i) slot(i)->~T();
    size_ = 0;
  }
  bool push_back(const T& v) {
    if (size_ == N) return false;
    new (slot(size_)) T(v);
    ++size_;
    return true;
  }
  void erase(std::size_t i) {
    assert(i < size_);
    for (std::size_t k = i + 1; k < size_; ++k) *slot(k - 1) = *slot(k);
    slot(size_ - 1)->~T();
    --size_;
  }
  T& operator[](std::size_t i) {
    assert(i < size_);
    return *slot(i);
  }
  const T& operator[](std::size_t i) const {
    assert(i < size_);
    return *slot(i);
  }
  T* begin() { return slot(0); }
  T* end() { return slot(size_); }
  const T* begin() const { return slot(0); }
  const T* end() const { return slot(size_); }

 private:
  void copyFrom(const FixedVector& o) {
    for (std::size_t i = 0; i < o.size_; ++i) new (slot(i)) T(*o.slot(i));
    size_ = o.size_;
  }
  T* slot(std::size_t i) { return std::launder(reinterpret_cast<T*>(storage_)) + i; }
  const T* slot(std::size_t i) const {
    return std::launder(reinterpret_cast<const T*>(storage_)) + i;
  }
  alignas(T) unsigned char storage_[N * sizeof(T)];
  std::size_t size_ = 0;
};

}  // namespace relpos
