#pragma once
// `linkage geometry --distance-from POINT`: the distance map, its loci and the injectivity radius as CSV,
// an equirectangular PNG map and JSON (docs/geometry.md, "Distance map, cut and conjugate locus").
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "scene/scene.hpp"

namespace sl {

struct DistanceMapRequest {
  std::string point;  // "start", JSON text or a file holding it
  int grid = 256;
  std::string csv;    // empty: standard output (unless --maps or --json is given)
  std::string maps;   // folder: distance.png
  bool json = false;  // the summary and the loci as JSON on standard output
  bool quiet = false;
  std::vector<std::string> formats;
  // --points: the distance at these chart-0 points (phi, t), exact (shortestArrival), in place of the grid's CSV.
  std::vector<Eigen::Vector2d> points;
};

// Writes what was asked; returns what the summary line says.
std::string runDistanceMap(const Scene& scene, const DistanceMapRequest& request);

}  // namespace sl
