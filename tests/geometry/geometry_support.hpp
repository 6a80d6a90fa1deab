#pragma once
// Chains and sphere points shared by the geometry tests.

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"

namespace sl::testing {

struct MassSetting {
  std::string name;
  Chain chain;
};

// The issue's mass settings at base length L: unit hinge masses (the spec's case), rods only (hinge masses 0,
// unit rod masses: every hinge still carries mass from its rods, as Chain::validate requires), heavy rods,
// and an asymmetric mix.
inline std::vector<MassSetting> massSettings(double L) {
  std::vector<MassSetting> settings;
  settings.push_back({"unit hinges", Chain::uniform(4, L)});
  Chain rods = Chain::uniform(4, L);
  rods.hingeMasses.setZero();
  rods.rodMasses.setOnes();
  settings.push_back({"rods only", rods});
  Chain heavy = Chain::uniform(4, L);
  heavy.rodMasses.setConstant(5.0);
  settings.push_back({"heavy rods", heavy});
  Chain mixed = Chain::uniform(4, L);
  mixed.hingeMasses << 0.5, 2.0, 1.0;
  mixed.rodMasses << 0.0, 1.5, 0.25, 3.0;
  settings.push_back({"asymmetric", mixed});
  return settings;
}

// For RecordProperty: 2 significant digits, scientific.
inline std::string scientific(double value) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific << value;
  return out.str();
}

inline const std::vector<double>& issueBaseLengths() {
  static const std::vector<double> lengths = {2.2, 3.0, 3.5, 3.9};
  return lengths;
}

inline Eigen::Vector3d chartZeroPoint(double phi, double t) {
  return {std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)};
}

// Random points, the poles of both charts, points on and next to chart 0's seams t = +-pi/2 and poles.
inline std::vector<Eigen::Vector3d> testPoints(int randomCount, unsigned seed = 11) {
  std::vector<Eigen::Vector3d> points;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  for (int i = 0; i < randomCount; ++i)
    points.push_back(Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) points.push_back(sign * Eigen::Vector3d::Unit(axis));
  for (double phi : {-1.2, -0.3, 0.0, 0.7, M_PI / 2 - 1e-8, -M_PI / 2 + 1e-6})
    for (double t : {-M_PI / 2, M_PI / 2, M_PI / 2 + 1e-9, 0.0, M_PI}) points.push_back(chartZeroPoint(phi, t));
  return points;
}

}  // namespace sl::testing
