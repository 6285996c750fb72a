// Named benchmark workloads over the public core API, shared by Google Benchmark and the node
// runner.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace niwa {

// The timed part of a workload. It returns a checksum of its result so the work cannot be optimized
// away (and so native and WASM runs can be seen to compute the same thing).
using WorkloadBody = std::function<double()>;

struct Workload {
  std::string name;  // "grow/sakura-15y", "light/grid-2000", ...
  std::string note;  // one line: what is timed
  // Untimed setup (grow the tree to mesh, make the spheres, ...); returns the timed body.
  std::function<WorkloadBody()> prepare;
  bool once = false;  // slow (tens of seconds): timed once, without warm-up or repeats
  // Optional: how many units (e.g. internode-steps) one run of the body handles, filled in by
  // prepare(); when > 0 the runners also report the time per unit (`unit` names it).
  std::string unit = "";
  std::shared_ptr<double> units = std::make_shared<double>(0.0);
};

// Every workload, in table order.
const std::vector<Workload>& Workloads();

// Each study's workloads, in its own <study>_workloads.cpp; Workloads() appends them.
std::vector<Workload> GeomWorkloads();  // geom_workloads.cpp

}  // namespace niwa
