// CPU seconds of the test process, for the budget tests that compare a job's time with its
// estimate. Natively std::clock; under node (the WASM build) the process's user + system time,
// because Emscripten's clock() is the wall clock, which other jobs on a shared machine stretch.
// Does not: time other processes or threads apart.
#pragma once

#include <ctime>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace niwa::test {

inline double CpuSeconds() {
#ifdef __EMSCRIPTEN__
  // clang-format off
  return EM_ASM_DOUBLE({ const u = process.cpuUsage(); return (u.user + u.system) / 1e6; });
  // clang-format on
#else
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
#endif
}

}  // namespace niwa::test
