// RepairContour: §4.4 loop removal, else the union's largest ring (see contour_repair.h).
#include "terrain/contour_repair.h"

#include <cmath>

#include "terrain/generate.h"
#include "terrain/loops.h"
#include "terrain/offset.h"
#include "terrain/polygon.h"

namespace niwa::terrain {

Result<ContourRepair> RepairContour(const Ring& ring) {
  Result<Ring> checked = CheckSeed(ring);
  ContourRepair out;
  if (checked.ok()) {
    out.ring = ring;
    return out;
  }
  // Only a ring of 3 to kMaxSeedPoints finite points can be repaired; otherwise CheckSeed's line.
  if (ring.size() < 3 || ring.size() > kMaxSeedPoints) return checked.status();
  for (const Vec2& v : ring)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::fabs(v.x) > kMaxCoordinate ||
        std::fabs(v.y) > kMaxCoordinate)
      return checked.status();
  int removed = 0;
  const Ring snapped = Snap(ring);
  // §4.4 method 2 with the table's default run (loop_run 5), whatever the state's rows.
  Result<Ring> untwisted = CheckSeed(Normalise(UntwistRing(snapped, 2, 5, &removed)));
  if (!untwisted.ok()) {
    ShrinkCounts counts;
    std::vector<Ring> pieces = PositiveUnion({Normalise(snapped)}, &counts);
    const Ring* best = nullptr;
    for (const Ring& piece : pieces)
      if (!best || std::fabs(Area(piece)) > std::fabs(Area(*best))) best = &piece;
    if (best) untwisted = CheckSeed(*best);
    out.method = "union";
  } else {
    out.method = "loops";
  }
  if (!untwisted.ok()) {
    return Status::Error(
        "contour", "crosses itself and could not be repaired; must be one simple closed loop");
  }
  out.ring = std::move(untwisted).value();
  out.repaired = true;
  out.loops_removed = removed;
  out.reason = checked.status().Line();
  return out;
}

}  // namespace niwa::terrain
