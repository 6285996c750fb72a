// Google Benchmark binary (native only): registers every shared workload as one benchmark, in ms.
#include <benchmark/benchmark.h>

#include <memory>

#include "process_heap.h"
#include "workloads.h"

namespace niwa {
namespace {

void RegisterAll() {
  for (const Workload& w : Workloads()) {
    // Prepared on first use and kept, since Google Benchmark calls the function several times.
    auto body = std::make_shared<WorkloadBody>();
    const Workload* workload = &w;
    benchmark::internal::Benchmark* bench =
        benchmark::RegisterBenchmark(w.name.c_str(), [workload, body](benchmark::State& state) {
          if (!*body) *body = workload->prepare();
          for (auto _ : state) benchmark::DoNotOptimize((*body)());
          if (*workload->units > 0) {  // e.g. sway: seconds per internode-step (shown as 24.4n)
            state.counters["per_" + workload->unit] =
                benchmark::Counter(*workload->units, benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
          }
        });
    bench->Unit(benchmark::kMillisecond);
    if (w.once) bench->Iterations(1);  // slow: one timed run
  }
}

}  // namespace
}  // namespace niwa

int main(int argc, char** argv) {
  niwa::KeepFreedMemoryForReuse();  // as the CLI does (native_cli/process_heap.h)
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  niwa::RegisterAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
