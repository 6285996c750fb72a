// Plain benchmark runner (native and WASM under node): times every workload, prints JSON lines.
//
// Usage: niwa_bench_runner [--filter SUBSTRING] [--min-ms MS] [--min-reps N] [--max-reps N]
// [--list] Each workload is prepared once, run once untimed (warm-up), then repeated until it has
// run at least --min-reps times and for at least --min-ms in total (never more than --max-reps).
// One line per workload:
// {"build":"native","workload":"grow/sakura-15y","ms":median,"min_ms":..,"reps":.., "check":..},
// with "check" the workload's checksum (equal on both builds when results agree), plus
// "unit", "units" and "ns_per_unit" (median) for workloads that count units (sway:
// internode-steps), natively "cpu_ns_per_unit" (the process's CPU time over the timed
// repetitions), and the workload's size under its own name (moss rocks: "triangles").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "process_heap.h"
#include "workloads.h"

namespace niwa {
namespace {

constexpr const char* kBuild = NIWA_BUILD_NAME;  // "native" or "wasm", from cmake/<platform>.cmake

struct Options {
  std::string filter;
  double min_ms = 300;
  int min_reps = 3;
  int max_reps = 200;
  bool list = false;
};

bool ParseOptions(int argc, char** argv, Options* o) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    bool has_value = i + 1 < argc;
    if (arg == "--list") {
      o->list = true;
    } else if (arg == "--filter" && has_value) {
      o->filter = argv[++i];
    } else if (arg == "--min-ms" && has_value) {
      o->min_ms = std::atof(argv[++i]);
    } else if (arg == "--min-reps" && has_value) {
      o->min_reps = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--max-reps" && has_value) {
      o->max_reps = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr,
                   "usage: niwa_bench_runner [--filter SUBSTRING] [--min-ms MS] [--min-reps N] "
                   "[--max-reps N] [--list]\n");
      return false;
    }
  }
  o->max_reps = std::max(o->max_reps, o->min_reps);
  return true;
}

double ElapsedMs(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void Run(const Workload& w, const Options& o) {
  WorkloadBody body = w.prepare();
  std::vector<double> times;
  double total = 0;
  double check = 0;
  if (w.once) {  // slow workload: one timed run is the measurement
    auto start = std::chrono::steady_clock::now();
    check = body();
    times.push_back(ElapsedMs(start));
  } else {
    check = body();  // warm-up
  }
  const std::clock_t cpu_start = std::clock();
  while (!w.once && (static_cast<int>(times.size()) < o.min_reps ||
                     (total < o.min_ms && static_cast<int>(times.size()) < o.max_reps))) {
    auto start = std::chrono::steady_clock::now();
    double c = body();
    double ms = ElapsedMs(start);
    if (c != check) check = -1;  // a workload that is not deterministic shows up as -1
    times.push_back(ms);
    total += ms;
  }
  // The process's CPU time over the timed repetitions (native: clock() is CPU time; in WASM it is
  // not, so not printed): on a loaded machine the wall-clock median is not evidence.
  const double cpu_ms_per_rep = w.once ? 0.0
                                       : 1000.0 * static_cast<double>(std::clock() - cpu_start) /
                                             CLOCKS_PER_SEC / static_cast<double>(times.size());
  std::sort(times.begin(), times.end());
  double median = times[times.size() / 2];
  if (times.size() % 2 == 0) median = 0.5 * (median + times[times.size() / 2 - 1]);
  std::string per_unit;
  if (*w.units > 0) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, ",\"unit\":\"%s\",\"units\":%.0f,\"ns_per_unit\":%.3f",
                  w.unit.c_str(), *w.units, median * 1e6 / *w.units);
    per_unit = buffer;
  }
  if (*w.units > 0 && cpu_ms_per_rep > 0 && std::string(kBuild) == "native") {
    char buffer[80];
    std::snprintf(buffer, sizeof buffer, ",\"cpu_ns_per_unit\":%.3f",
                  cpu_ms_per_rep * 1e6 / *w.units);
    per_unit += buffer;
  }
  if (*w.size > 0 && !w.size_name.empty()) {
    char buffer[120];
    std::snprintf(buffer, sizeof buffer, ",\"%s\":%.0f", w.size_name.c_str(), *w.size);
    per_unit += buffer;
  }
  std::printf(
      "{\"build\":\"%s\",\"workload\":\"%s\",\"ms\":%.4f,\"min_ms\":%.4f,\"reps\":%zu,"
      "\"check\":%.17g%s}\n",
      kBuild, w.name.c_str(), median, times.front(), times.size(), check, per_unit.c_str());
  std::fflush(stdout);
}

}  // namespace
}  // namespace niwa

int main(int argc, char** argv) {
  niwa::KeepFreedMemoryForReuse();  // as the CLI does (native_cli/process_heap.h)
  niwa::Options options;
  if (!niwa::ParseOptions(argc, argv, &options)) return 2;
  for (const niwa::Workload& w : niwa::Workloads()) {
    if (!options.filter.empty() && w.name.find(options.filter) == std::string::npos) continue;
    if (options.list) {
      std::printf("%-22s %s\n", w.name.c_str(), w.note.c_str());
    } else {
      niwa::Run(w, options);
    }
  }
  return 0;
}
