// Heap settings for native batch runs (CLI, benchmarks): keep freed memory in the process, as the
// WASM heap does.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace niwa {

// glibc maps every block of 128 KiB or more afresh and returns it on free, so a run that grows and
// frees large vectors year after year (a tree's branches, meshes, .glb buffers) spends much of its
// time in page faults: maple at 40 years took 400 ms instead of 270 ms, and writing a sakura .glb
// 350 ms instead of 20 ms. Raising both thresholds keeps such blocks in the heap for reuse, which
// is what the WASM build's heap does anyway. Elsewhere (musl, WASM) this does nothing.
inline void KeepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace niwa
