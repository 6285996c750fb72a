// Two lanes for the bark model's passes (four_layer.cpp): a job run as lane 0 here and lane 1 on
// one worker thread that lives as long as the lanes (native builds with NIWA_HAVE_THREADS), or
// both here, lane 0 then lane 1 (one lane asked for, or a build without threads: WASM). Run
// returns when both lanes are done. The passes it splits are independent per spring slot and per
// node, so the bits do not depend on the lanes (FourLayer.TwoLanesGiveTheSameBits). Waiting spins
// briefly, then sleeps on a condition variable (the machine may be busy). Does not: split the work
// (the job takes its half by the lane index), or catch a job's exceptions (the passes throw none).
#pragma once

#include <functional>
#include <memory>

namespace niwa::bark {

class StepLanes {
 public:
  // lanes = 2 asks for the worker thread (where the build has threads); 1 runs both halves here.
  explicit StepLanes(int lanes);
  ~StepLanes();
  StepLanes(const StepLanes&) = delete;
  StepLanes& operator=(const StepLanes&) = delete;

  // job(0) here and job(1) on the worker (or here after job(0)); returns when both returned.
  void Run(const std::function<void(int)>& job);
  // True when lane 1 runs on its own thread.
  bool threaded() const;

 private:
  struct Worker;
  std::unique_ptr<Worker> worker_;
};

// Whether this build can run lanes on threads (native: NIWA_HAVE_THREADS).
bool StepLanesHaveThreads();

}  // namespace niwa::bark
