// Two lanes for the bark model's passes: a worker thread handed a job per pass, or both lanes here.
#include "bark/step_lanes.h"

#if NIWA_HAVE_THREADS
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#endif

namespace niwa::bark {

#if NIWA_HAVE_THREADS
namespace {
constexpr int kSpins = 4000;  // polls of the other side before sleeping (a few microseconds)
}  // namespace

struct StepLanes::Worker {
  std::mutex mu;
  std::condition_variable posted_cv, done_cv;
  std::atomic<uint64_t> posted{0}, done{0};
  const std::function<void(int)>* job = nullptr;
  bool stop = false;
  std::thread thread;

  Worker() : thread([this] { Loop(); }) {}
  ~Worker() {
    {
      std::lock_guard<std::mutex> lock(mu);
      stop = true;
    }
    posted_cv.notify_one();
    thread.join();
  }

  void Loop() {
    uint64_t seen = 0;
    for (;;) {
      for (int i = 0; i < kSpins && posted.load(std::memory_order_acquire) == seen; ++i) {
      }
      const std::function<void(int)>* todo = nullptr;
      {
        std::unique_lock<std::mutex> lock(mu);
        posted_cv.wait(lock, [&] { return stop || posted.load() != seen; });
        if (stop) return;
        seen = posted.load();
        todo = job;
      }
      (*todo)(1);
      {
        std::lock_guard<std::mutex> lock(mu);
        done.store(seen, std::memory_order_release);
      }
      done_cv.notify_one();
    }
  }

  void Run(const std::function<void(int)>& j) {
    uint64_t ticket = 0;
    {
      std::lock_guard<std::mutex> lock(mu);
      job = &j;
      ticket = posted.load() + 1;
      posted.store(ticket, std::memory_order_release);
    }
    posted_cv.notify_one();
    j(0);
    for (int i = 0; i < kSpins && done.load(std::memory_order_acquire) != ticket; ++i) {
    }
    std::unique_lock<std::mutex> lock(mu);
    done_cv.wait(lock, [&] { return done.load() == ticket; });
  }
};

StepLanes::StepLanes(int lanes) {
  if (lanes >= 2) worker_ = std::make_unique<Worker>();
}

void StepLanes::Run(const std::function<void(int)>& job) {
  if (worker_) {
    worker_->Run(job);
    return;
  }
  job(0);
  job(1);
}

bool StepLanesHaveThreads() { return true; }
#else
struct StepLanes::Worker {};

StepLanes::StepLanes(int) {}

void StepLanes::Run(const std::function<void(int)>& job) {
  job(0);
  job(1);
}

bool StepLanesHaveThreads() { return false; }
#endif

StepLanes::~StepLanes() = default;

bool StepLanes::threaded() const { return worker_ != nullptr; }

}  // namespace niwa::bark
