#include "batch_memory.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define KLUENG_SANITIZED_ALLOCATOR 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define KLUENG_SANITIZED_ALLOCATOR 1
#endif

namespace klueng::cli {

void prepareBatchMemory() {
#if defined(__linux__) && defined(__GLIBC__) && !defined(KLUENG_SANITIZED_ALLOCATOR)
  // Every allocation from the one heap (no separate mmap per big vector, each
  // faulted in anew), and nothing trimmed back to the kernel before exit.
  // Both above the reserve below: else it would be mapped apart from the heap
  // and unmapped again by free(), or trimmed off the heap.
  constexpr int kLarge = 1536 << 20;
  mallopt(M_MMAP_THRESHOLD, kLarge);
  mallopt(M_TRIM_THRESHOLD, kLarge);
  // One heap for every thread: the check's second thread (the tool inference's
  // recorded run, half the model) would else take an arena of its own, mapped
  // apart and faulted in 4 KiB pages (issue 40: a quarter of `check`'s time).
  mallopt(M_ARENA_MAX, 1);
  // Grow the heap once by a generous reserve (address space only: nothing is
  // touched) and mark it for huge pages; the allocations that follow reuse it.
  // 1 GiB: a million-block program's check takes 400 MB, and what lies past
  // the reserve is faulted in 4 KiB pages, three times slower here.
  constexpr std::size_t kReserve = std::size_t{1} << 30;
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  void* block = std::malloc(kReserve);
  if (!block) return;
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t from = (start + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t to = (start + kReserve) & ~(kHugePage - 1);
  std::free(block);
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

}  // namespace klueng::cli
