// Shared shapes for the garden's .glb: farthest-point representatives and the nearest assignment.
#include "compose/garden_shapes.h"

#include <cmath>
#include <limits>

namespace niwa::compose {

double ShapeDistance(const TreeShape& a, const TreeShape& b, double mean_height,
                     double mean_reach) {
  const double h = mean_height > 0 ? 1.0 / mean_height : 0.0;
  const double r = mean_reach > 0 ? 1.0 / mean_reach : 0.0;
  const double dh = (a.height - b.height) * h;
  const double dr = (a.reach - b.reach) * r;
  const double dl = (a.lean - b.lean) * r;
  return std::sqrt(dh * dh + dr * dr + dl * dl);
}

std::vector<int> ShareShapes(const std::vector<TreeShape>& shapes, int n) {
  const int count = static_cast<int>(shapes.size());
  std::vector<int> rep_of(shapes.size());
  for (int i = 0; i < count; ++i) rep_of[i] = i;
  if (n < 1 || count <= n) return rep_of;
  TreeShape mean;
  for (const TreeShape& s : shapes) {
    mean.height += s.height;
    mean.reach += s.reach;
    mean.lean += s.lean;
  }
  mean.height /= count;
  mean.reach /= count;
  mean.lean /= count;
  const auto dist = [&](const TreeShape& a, const TreeShape& b) {
    return ShapeDistance(a, b, mean.height, mean.reach);
  };
  // The first representative: the shape nearest the mean.
  std::vector<int> reps;
  int first = 0;
  for (int i = 1; i < count; ++i)
    if (dist(shapes[i], mean) < dist(shapes[first], mean)) first = i;
  reps.push_back(first);
  // nearest[i]: shape i's distance to its nearest representative so far.
  std::vector<double> nearest(shapes.size());
  for (int i = 0; i < count; ++i) nearest[i] = dist(shapes[i], shapes[first]);
  while (static_cast<int>(reps.size()) < n) {
    int far = -1;
    for (int i = 0; i < count; ++i)
      if (far < 0 || nearest[i] > nearest[far]) far = i;
    if (nearest[far] <= 0) break;  // every shape is already one of them
    reps.push_back(far);
    for (int i = 0; i < count; ++i)
      nearest[i] = std::fmin(nearest[i], dist(shapes[i], shapes[far]));
  }
  for (int i = 0; i < count; ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (int r : reps) {
      const double d = r == i ? -1.0 : dist(shapes[i], shapes[r]);
      if (d < best) {
        best = d;
        rep_of[i] = r;
      }
    }
  }
  return rep_of;
}

}  // namespace niwa::compose
