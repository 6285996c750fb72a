// The one contract every study's run keeps (tree, ivy, terrain; moss, bark and the garden next), so
// the CLI, the embind sessions and the composer (core/compose) drive every study through one shape.
// Does not: parse flags, read or write files, know a page, a flag or a panel label (errors name
// state fields; each front end maps a field to its own word through run/field_names.h), hold any
// study's state type (each study's run adds its own Start(state, budget) and Update(state)), or
// include any study.
//
// A study's run (core/<study>/<study>_run.{h,cpp}):
//   static Result<XRun> Start(const XState&, const Budget&)  -- estimates checked before work
//   Status Advance(const Observer&)   -- to the state's target in the study's unit, with progress
//                                        and cancel; errors name state fields or the budget
//   Status Update(const XState&)      -- a new state: re-does only the earliest stage whose rows
//                                        changed and the ones after it (the table's stage column)
//   Parts(), Document(), StatsJson(), Hash(prefix), ExportEstimate(format)  -- its outputs
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/gltf_writer.h"

namespace niwa::run {

// Where an Advance is: phase ("tree", "grow", "mesh", "levels"), units done of total.
struct Progress {
  std::string phase;
  double done = 0;
  double total = 0;
};

// Called between units of work; returns false to cancel. A cancelled Advance returns
// CancelledStatus() and leaves the run as it was before that Advance began.
using Observer = std::function<bool(const Progress&)>;

// The field of a cancelled run's Status ("run: cancelled").
inline Status CancelledStatus() { return Status::Error("run", "cancelled"); }
inline bool IsCancelled(const Status& s) {
  return !s.ok() && s.field() == "run" && s.message() == "cancelled";
}

// One named part of a study's output, in the one world frame: metres, y up, the ground at y = 0
// where the study has a ground. A composer places parts with a node transform; a study never does.
struct Part {
  std::string name;  // "bark", "stems", "leaves", "terrain", ...; unique within a run
  gltf::Mode mode = gltf::Mode::kTriangles;
  geom::TriMesh mesh;
  gltf::Material material;  // textures referenced by index into `textures`
  std::vector<gltf::Texture> textures;
};

// The stages of a table (params/param_table.h Stage), as a bit set: which ones a new state
// invalidates, so a run re-does the earliest and those after it.
using StageMask = uint32_t;

// The interface the composer drives; each study's run derives from it.
class StudyRun {
 public:
  virtual ~StudyRun() = default;
  virtual const char* study() const = 0;  // "tree", "ivy", "terrain"
  virtual const char* unit() const = 0;   // "years", "steps", "levels"
  virtual int done() const = 0;           // units advanced so far
  virtual int target() const = 0;         // units the state asks for
  virtual Status Advance(const Observer& observer) = 0;
  virtual std::vector<Part> Parts() const = 0;
  virtual Result<gltf::Document> Document() const = 0;
  virtual std::string StatsJson() const = 0;
  virtual std::string Hash(const std::string& prefix) const = 0;
  // What writing `format` ("glb", "json", "svg", ...) of the current result needs, added to what
  // the run holds; front ends check it against their budget before exporting.
  virtual Result<Estimate> ExportEstimate(const std::string& format) const = 0;
};

}  // namespace niwa::run
