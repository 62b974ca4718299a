#pragma once
// The CLI is a batch process: it builds one big program model, uses it once
// and exits. Most of what it used to wait for on a 100k-block program was the
// kernel handing it fresh 4 KiB pages (12,800 page faults for `check`, a
// third of its time). This lets the C library take its heap in 2 MiB
// transparent huge pages instead (one fault per 2 MiB), for every thread,
// and keeps freed memory for reuse rather than giving it back and faulting
// it in again.
#include <utility>

namespace klueng::cli {

// Leaves the last big model (a 100k-block job) for the process's exit to hand
// back whole: freeing it block by block costs milliseconds the user waits for.
// Held through a static pointer, so leak checkers see it as reachable.
// One kept value per type: a second call frees the first.
template <class T>
T& keepUntilExit(T&& value) {
  static T* kept = nullptr;
  delete kept;
  kept = new T(std::move(value));
  return *kept;
}

// Call once at the start of main. Does nothing where it cannot help (not
// glibc on Linux, or a sanitizer's allocator).
void prepareBatchMemory();

}  // namespace klueng::cli
