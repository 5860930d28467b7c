// Allocator with a fixed alignment, for arrays of fixed-size records read in a hot loop: a
// 128-byte record aligned to 128 bytes spans exactly two cache lines (with malloc's 16-byte
// alignment it straddles three), and its first line can carry everything a quick rejection needs.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace plyimpact {

template <class T, std::size_t Align>
struct AlignedAllocator {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = AlignedAllocator<U, Align>;
  };
  AlignedAllocator() = default;
  template <class U>
  AlignedAllocator(const AlignedAllocator<U, Align>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(Align))); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, std::align_val_t(Align)); }
  template <class U>
  bool operator==(const AlignedAllocator<U, Align>&) const {
    return true;
  }
};

template <class T, std::size_t Align>
using AlignedVector = std::vector<T, AlignedAllocator<T, Align>>;

}  // namespace plyimpact
