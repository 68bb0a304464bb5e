// Cache-line aligned std::vector, so SIMD loops over structure-of-arrays data start on a
// 64-byte boundary (one AVX-512 register) without peeling.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace tri {

template <typename T, std::size_t Alignment = 64> struct AlignedAllocator {
  using value_type = T;
  template <typename U> struct rebind { using other = AlignedAllocator<U, Alignment>; };

  AlignedAllocator() noexcept = default;
  template <typename U> AlignedAllocator(const AlignedAllocator<U, Alignment> &) noexcept {}

  T *allocate(std::size_t n) {
    return static_cast<T *>(::operator new(n * sizeof(T), std::align_val_t(Alignment)));
  }
  void deallocate(T *p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(Alignment)); }

  template <typename U> bool operator==(const AlignedAllocator<U, Alignment> &) const noexcept {
    return true;
  }
  template <typename U> bool operator!=(const AlignedAllocator<U, Alignment> &) const noexcept {
    return false;
  }
};

template <typename T> using AlignedVector = std::vector<T, AlignedAllocator<T>>;

} // namespace tri
