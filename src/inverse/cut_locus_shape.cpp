// The shape of a distance map's cut locus (inverse/distance_map.hpp): its graph (components, vertices, edges and
// cycles, by the faces of the map's grid it cuts) and the cusps it ends in on the conjugate locus.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "inverse/distance_map.hpp"

namespace sl {

CutGraphShape cutGraphShape(const DistanceMap& map) {
  const int rows = static_cast<int>(map.phis.size()), cols = static_cast<int>(map.ts.size());
  const int faces = (rows - 1) * cols;
  // Faces first, then one vertex per conjugate cut point (the closure's end points).
  std::vector<int> parent(static_cast<std::size_t>(faces) + map.conjugateLocus.size(), -1);
  auto find = [&](int f) {
    while (parent[static_cast<std::size_t>(f)] != f) f = parent[static_cast<std::size_t>(f)];
    return f;
  };
  auto join = [&](int f, int g) {
    const int rf = find(f), rg = find(g);
    if (rf != rg) parent[static_cast<std::size_t>(rf)] = rg;
  };
  CutGraphShape shape;
  auto touch = [&](int f) {
    if (parent[static_cast<std::size_t>(f)] < 0) {
      parent[static_cast<std::size_t>(f)] = f;
      ++shape.vertices;
    }
  };
  for (const CutEdge& e : map.cutLocus) {
    const int i = e.a / cols, j = e.a % cols;
    int f, g;
    if (e.b / cols == i) {  // along a row: the faces above and below
      f = (i - 1) * cols + j;
      g = i * cols + j;
    } else {  // along a column: the faces left and right
      f = i * cols + (j + cols - 1) % cols;
      g = i * cols + j;
    }
    touch(f);
    touch(g);
    ++shape.edges;
    join(f, g);
  }
  auto count = [&](int upTo) {
    int c = 0;
    for (int f = 0; f < upTo; ++f)
      if (parent[static_cast<std::size_t>(f)] >= 0 && find(f) == f) ++c;
    return c;
  };
  shape.edgeComponents = count(faces);
  // The closure: a conjugate cut point joins the cut faces within three faces of its own, and the next
  // conjugate cut point within three grid spacings.
  const double cell = std::numbers::pi / (rows - 1);
  const auto& locus = map.conjugateLocus;
  for (std::size_t k = 0; k < locus.size(); ++k) {
    if (!locus[k].cut) continue;
    const int self = faces + static_cast<int>(k);
    parent[static_cast<std::size_t>(self)] = self;
    const double phi = std::asin(std::clamp(locus[k].x.z(), -1.0, 1.0)), t = std::atan2(locus[k].x.y(), locus[k].x.x());
    const int fi = std::clamp(static_cast<int>((phi + std::numbers::pi / 2) / cell), 0, rows - 2);
    const int fj = static_cast<int>(std::floor((t + std::numbers::pi) / (2 * std::numbers::pi) * cols));
    for (int di = -3; di <= 3; ++di)
      for (int dj = -3; dj <= 3; ++dj) {
        const int i = fi + di, j = ((fj + dj) % cols + cols) % cols;
        if (i < 0 || i > rows - 2) continue;
        const int f = i * cols + j;
        if (parent[static_cast<std::size_t>(f)] >= 0) join(self, f);
      }
    const std::size_t previous = (k + locus.size() - 1) % locus.size();
    if (previous != k && locus[previous].cut && (locus[previous].x - locus[k].x).norm() < 3 * cell &&
        parent[static_cast<std::size_t>(faces) + previous] >= 0)
      join(self, faces + static_cast<int>(previous));
  }
  shape.components = count(static_cast<int>(parent.size()));
  return shape;
}

int conjugateCusps(const DistanceMap& map, double noise) {
  const auto& locus = map.conjugateLocus;
  if (locus.size() < 3) return 0;
  // From the largest distance once round, counting the turns of the distance beyond the noise; the start,
  // a maximum, counts once the walk has turned at all.
  std::size_t top = 0;
  for (std::size_t k = 1; k < locus.size(); ++k)
    if (locus[k].distance > locus[top].distance) top = k;
  bool descending = true;
  double extreme = locus[top].distance;
  int turns = 0;
  for (std::size_t k = 1; k <= locus.size(); ++k) {
    const double d = locus[(top + k) % locus.size()].distance;
    if (descending) {
      if (d < extreme)
        extreme = d;
      else if (d > extreme + noise) {
        ++turns;
        descending = false;
        extreme = d;
      }
    } else {
      if (d > extreme)
        extreme = d;
      else if (d < extreme - noise) {
        ++turns;
        descending = true;
        extreme = d;
      }
    }
  }
  return turns > 0 ? turns + 1 : 0;
}

}  // namespace sl
