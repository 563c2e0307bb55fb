// Big buffers a build fills once (node arrays, event lists): asks Linux to
// back them with 2 MiB pages. With transparent huge pages in "madvise" mode
// (Debian's default) every fresh 4 KiB page costs a fault on its first
// touch -- about 10 us on the virtual machine we measure on, so touching
// 64 MB took 175 ms, and 5-90 ms on 2 MiB pages. Elsewhere a no-op; the
// kernel may always refuse (then nothing changes but speed). Memory is
// taken in 2 MiB steps, so only buffers of a few MiB are worth advising.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ll {

// Advises the whole 2 MiB pages inside [data, data + bytes); call before the first touch.
inline void adviseHugePages([[maybe_unused]] void* data, [[maybe_unused]] size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#endif
}

// Buffers below this size are left on small pages (memory is taken in 2 MiB steps).
constexpr size_t kHugePagesWorthIt = size_t{4} << 20;

// v.reserve(n), the new storage advised first when it is big enough.
template <class T, class A>
void reserveOnHugePages(std::vector<T, A>& v, size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T, A> grown;
  grown.reserve(n);
  if (n * sizeof(T) >= kHugePagesWorthIt) adviseHugePages(grown.data(), n * sizeof(T));
  grown.assign(std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(grown);
}

// v.resize(n), the new storage advised before resize() first touches it.
template <class T, class A>
void resizeOnHugePages(std::vector<T, A>& v, size_t n) {
  reserveOnHugePages(v, n);
  v.resize(n);
}

}  // namespace ll
