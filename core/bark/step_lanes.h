// Two lanes for the bark model's passes (four_layer.cpp): a pass cut into chunks, the chunks shared
// by this thread, taking them from the front, and one worker thread that lives as long as the
// lanes (native builds with NIWA_HAVE_THREADS), taking them from the back, each claiming half of
// what is left at a time (guided self-scheduling), so a busy or sleeping worker costs a pass no
// more than its claimed chunks: the caller takes the rest. Without the worker (one lane asked for,
// or a build without threads: WASM) every chunk runs here in order. Run returns when every chunk
// is done. The passes it splits are independent per spring slot and per node, so the bits do not
// depend on which thread ran which chunk (FourLayer.TwoLanesGiveTheSameBits). An idle worker spins
// (pause) for about 50 µs, then yields for about 2 ms, then sleeps until the next pass is posted
// (the machine may be busy); the caller never waits for a worker to wake. Does not: choose the
// chunks (the job maps a chunk index to its nodes), or catch a job's exceptions (the passes throw
// none).
#pragma once

#include <functional>
#include <memory>

namespace niwa::bark {

class StepLanes {
 public:
  // lanes = 2 asks for the worker thread (where the build has threads); 1 runs every chunk here.
  explicit StepLanes(int lanes);
  ~StepLanes();
  StepLanes(const StepLanes&) = delete;
  StepLanes& operator=(const StepLanes&) = delete;

  // job(k) once for every chunk k in [0, chunks) (1 ≤ chunks ≤ 65535), some on the worker; returns
  // when all have returned. Chunks may run in any order and two at once.
  void Run(int chunks, const std::function<void(int)>& job);
  // True when chunks also run on a thread of their own.
  bool threaded() const;

 private:
  struct Worker;
  std::unique_ptr<Worker> worker_;
};

// Whether this build can run lanes on threads (native: NIWA_HAVE_THREADS).
bool StepLanesHaveThreads();

}  // namespace niwa::bark
