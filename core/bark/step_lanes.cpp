// Two lanes for the bark model's passes: chunks shared with a worker thread, or all of them here.
#include "bark/step_lanes.h"

#if NIWA_HAVE_THREADS
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#endif

namespace niwa::bark {

#if NIWA_HAVE_THREADS
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kSpinTime = std::chrono::microseconds(50);  // polls with pause before yielding
constexpr auto kYieldTime = std::chrono::milliseconds(2);  // then yields before sleeping

// The claim word: the pass's generation (32 bits), then the unclaimed chunks [front, back).
constexpr uint64_t Pack(uint32_t gen, uint32_t front, uint32_t back) {
  return (static_cast<uint64_t>(gen) << 32) | (static_cast<uint64_t>(back) << 16) | front;
}
uint32_t GenOf(uint64_t w) { return static_cast<uint32_t>(w >> 32); }
uint32_t FrontOf(uint64_t w) { return static_cast<uint32_t>(w & 0xffff); }
uint32_t BackOf(uint64_t w) { return static_cast<uint32_t>((w >> 16) & 0xffff); }

inline void CpuRelax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Polls `ready` with pause for kSpinTime, then yields until kYieldTime; true once it holds, false
// when the time ran out.
template <class F>
bool SpinThenYield(const F& ready) {
  const Clock::time_point start = Clock::now();
  for (int i = 1;; ++i) {
    if (ready()) return true;
    if (i % 64 == 0 && Clock::now() - start > kSpinTime) break;
    CpuRelax();
  }
  while (Clock::now() - start < kYieldTime) {
    if (ready()) return true;
    std::this_thread::yield();
  }
  return ready();
}

}  // namespace

struct StepLanes::Worker {
  alignas(64) std::atomic<uint64_t> claim{Pack(0, 0, 0)};
  std::atomic<const std::function<void(int)>*> job{nullptr};
  alignas(64) std::atomic<int> done{0};  // chunks of the current pass the worker finished
  alignas(64) std::atomic<int> sleeping{0};
  std::atomic<bool> stop{false};
  std::mutex mu;
  std::condition_variable posted_cv;
  uint32_t gen = 0;  // the caller's last pass
  std::thread thread;

  Worker() : thread([this] { Loop(); }) {}
  ~Worker() {
    stop.store(true);
    {
      std::lock_guard<std::mutex> lock(mu);
      posted_cv.notify_one();
    }
    thread.join();
  }

  // Claims half of pass g's unclaimed chunks (at least one) from the front or the back: false
  // when none are left (or another pass is posted).
  bool Claim(uint32_t g, bool front, int* first, int* count) {
    uint64_t w = claim.load(std::memory_order_acquire);
    for (;;) {
      const uint32_t f = FrontOf(w), b = BackOf(w);
      if (GenOf(w) != g || f >= b) return false;
      const uint32_t k = std::max<uint32_t>(1, (b - f) / 2);
      const uint64_t next = front ? Pack(g, f + k, b) : Pack(g, f, b - k);
      if (claim.compare_exchange_weak(w, next, std::memory_order_acq_rel,
                                      std::memory_order_acquire)) {
        *first = static_cast<int>(front ? f : b - k);
        *count = static_cast<int>(k);
        return true;
      }
    }
  }

  void Loop() {
    uint32_t seen = 0;
    for (;;) {
      auto posted = [&] { return stop.load() || GenOf(claim.load()) != seen; };
      if (!SpinThenYield(posted)) {
        std::unique_lock<std::mutex> lock(mu);
        sleeping.store(1);
        posted_cv.wait(lock, posted);
        sleeping.store(0);
      }
      if (stop.load()) return;
      seen = GenOf(claim.load(std::memory_order_acquire));
      // Pass `seen`'s job, or a later one's: then every chunk of `seen` is claimed and Claim fails.
      const std::function<void(int)>* todo = job.load(std::memory_order_acquire);
      int first = 0, count = 0;
      while (Claim(seen, false, &first, &count)) {
        for (int k = first; k < first + count; ++k) (*todo)(k);
        done.fetch_add(count, std::memory_order_release);
      }
    }
  }

  void Run(int chunks, const std::function<void(int)>& j) {
    ++gen;
    job.store(&j, std::memory_order_relaxed);
    done.store(0, std::memory_order_relaxed);
    claim.store(Pack(gen, 0, static_cast<uint32_t>(chunks)));
    if (sleeping.load()) {
      std::lock_guard<std::mutex> lock(mu);
      posted_cv.notify_one();
    }
    int mine = 0, first = 0, count = 0;
    while (Claim(gen, true, &first, &count)) {
      for (int k = first; k < first + count; ++k) j(k);
      mine += count;
    }
    // The worker's claimed chunks: it is running them (or was preempted doing so).
    auto finished = [&] { return mine + done.load(std::memory_order_acquire) == chunks; };
    while (!SpinThenYield(finished)) {
    }
  }
};

StepLanes::StepLanes(int lanes) {
  if (lanes >= 2) worker_ = std::make_unique<Worker>();
}

void StepLanes::Run(int chunks, const std::function<void(int)>& job) {
  if (worker_) {
    worker_->Run(chunks, job);
    return;
  }
  for (int k = 0; k < chunks; ++k) job(k);
}

bool StepLanesHaveThreads() { return true; }
#else
struct StepLanes::Worker {};

StepLanes::StepLanes(int) {}

void StepLanes::Run(int chunks, const std::function<void(int)>& job) {
  for (int k = 0; k < chunks; ++k) job(k);
}

bool StepLanesHaveThreads() { return false; }
#endif

StepLanes::~StepLanes() = default;

bool StepLanes::threaded() const { return worker_ != nullptr; }

}  // namespace niwa::bark
