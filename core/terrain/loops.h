// Loop removal (§4.4, Fig 18): a contour twisted by midpoint displacement or phase randomisation is
// untwisted by method 1 (delete faces with fewer segments than a threshold) or method 2 (walk from
// a long run and cut from each self-intersection X to its second occurrence). Does not: decide
// whether the untwisted ring is simple (the caller verifies and falls back to the union).
#pragma once

#include <vector>

#include "terrain/contour.h"
#include "terrain/polygon.h"

namespace niwa::terrain {

// One item of a point sequence with its self-intersections inserted: a plain point (label −1)
// or an occurrence of intersection `label` (each label occurs exactly twice).
struct SeqItem {
  int label = -1;
  int id = 0;  // caller's name for the item (the Fig 18 number, or an index)
};

// Method 2 on a closed sequence: start at the first plain point of a run of ≥ min_run plain points
// (the longest run if none is that long), walk, and at each intersection X delete from X up to just
// before its other occurrence. Returns the kept items in walking order, starting at that point.
std::vector<SeqItem> RemoveLoopsMethod2(const std::vector<SeqItem>& seq, int min_run, int* removed);
// Method 1 on a closed sequence: repeatedly take an innermost loop X..X (no other intersection
// inside); if its face has fewer than min_segments segments, collapse it to X. Same start as
// method 2. Loops of larger faces are kept (their X stays an intersection).
// Each pass is a walk of the sequence (one per loop found: n·k for k loops); with `work`, counted
// (polygon.h SweepWork) and given up past its most.
std::vector<SeqItem> RemoveLoopsMethod1(const std::vector<SeqItem>& seq, int min_segments,
                                        int* removed, SweepWork* work = nullptr);

// A ring with its self-intersections inserted and loops removed by the method (1 or 2); the
// result may still be non-simple (the caller checks). *removed counts the loops cut. With `work`,
// its sweep and walks are counted; past its most, work->stopped and the result means nothing.
Ring UntwistRing(const Ring& ring, int method, int threshold, int* removed,
                 SweepWork* work = nullptr);

}  // namespace niwa::terrain
