// A heap meter for the budget tests: bytes currently allocated through operator new and their peak
// since Reset, to compare an estimate with what the work actually allocated. Include it in one
// test file of a binary with NIWA_ALLOC_METER_DEFINE defined first (that file then replaces the
// global operator new/delete); other files of the binary include it plainly. Does not: count
// malloc calls that bypass operator new, or aligned (align_val_t) allocations.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace niwa::test {

struct AllocMeter {
  static std::atomic<long long>& Current() {
    static std::atomic<long long> bytes{0};
    return bytes;
  }
  static std::atomic<long long>& Peak() {
    static std::atomic<long long> bytes{0};
    return bytes;
  }
  // Starts a measurement: the peak becomes the current figure.
  static long long Reset() {
    Peak() = Current().load();
    return Current().load();
  }
  // The peak since Reset, above `baseline` (Reset's return).
  static long long PeakAbove(long long baseline) { return Peak().load() - baseline; }
};

}  // namespace niwa::test

#ifdef NIWA_ALLOC_METER_DEFINE
namespace niwa::test::alloc_meter_detail {
// Each block carries its size in a 16-byte header (keeps the default alignment).
constexpr std::size_t kHeader = 16;
inline void* Allocate(std::size_t n) {
  void* raw = std::malloc(n + kHeader);
  if (raw == nullptr) throw std::bad_alloc();
  *static_cast<std::size_t*>(raw) = n;
  const long long now = AllocMeter::Current() += static_cast<long long>(n);
  long long peak = AllocMeter::Peak().load();
  while (now > peak && !AllocMeter::Peak().compare_exchange_weak(peak, now)) {
  }
  return static_cast<char*>(raw) + kHeader;
}
inline void Release(void* p) {
  if (p == nullptr) return;
  char* raw = static_cast<char*>(p) - kHeader;
  AllocMeter::Current() -= static_cast<long long>(*reinterpret_cast<std::size_t*>(raw));
  std::free(raw);
}
}  // namespace niwa::test::alloc_meter_detail

void* operator new(std::size_t n) { return niwa::test::alloc_meter_detail::Allocate(n); }
void* operator new[](std::size_t n) { return niwa::test::alloc_meter_detail::Allocate(n); }
void operator delete(void* p) noexcept { niwa::test::alloc_meter_detail::Release(p); }
void operator delete[](void* p) noexcept { niwa::test::alloc_meter_detail::Release(p); }
void operator delete(void* p, std::size_t) noexcept { niwa::test::alloc_meter_detail::Release(p); }
void operator delete[](void* p, std::size_t) noexcept {
  niwa::test::alloc_meter_detail::Release(p);
}
#endif
