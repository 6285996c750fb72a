// Heap settings for native batch runs (CLI, benchmarks): keep freed memory in the process, as the
// WASM heap does.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#endif

namespace niwa {

// glibc maps every block of 128 KiB or more afresh and returns it on free, so a run that grows and
// frees large vectors year after year (a tree's branches, meshes, .glb buffers) spends much of its
// time in page faults: maple at 40 years took 400 ms instead of 270 ms, and writing a sakura .glb
// 350 ms instead of 20 ms. Raising both thresholds keeps such blocks in the heap for reuse, which
// is what the WASM build's heap does anyway. Elsewhere (musl, WASM) this does nothing.
//
// The heap also starts as one 64 MiB block advised for transparent huge pages (where the kernel
// offers them on request, as Debian's "madvise" mode does): a fresh 'niwa tree grow --preset
// sakura-thesis --years 15' first-touched about 12 MB in 2,900 4-KiB page faults (7 ms of system
// time on the loaded test machine); in 2-MiB pages it takes about 500 faults and 3 ms (issue 17
// item 7). Blocks beyond the first 64 MiB are ordinary pages; untouched pages cost nothing.
inline void KeepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 64 << 20);
  // More than the heap has free (static constructors made it already): grows it by M_TOP_PAD.
  void* probe = std::malloc(std::size_t{1} << 20);
  const std::uintptr_t huge = std::uintptr_t{2} << 20;
  const std::uintptr_t start = (reinterpret_cast<std::uintptr_t>(probe) + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(huge - 1);
  if (end > start) (void)madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
  std::free(probe);
#endif
}

}  // namespace niwa
