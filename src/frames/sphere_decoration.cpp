#include "frames/sphere_decoration.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/curvature.hpp"
#include "geometry/curvature_grid.hpp"

namespace sl {
namespace {

const double kPi = std::acos(-1.0);

SphereField colourField(const ConfigurationSurface& surface, SphereColoring coloring) {
  SphereField field;
  field.phiCount = kSphereFieldRows;
  field.tCount = 2 * kSphereFieldRows;
  // Cell centres (frame_state.hpp): the texture's linear filtering then interpolates between exact values.
  std::vector<double> phis(field.phiCount), ts(field.tCount);
  for (int i = 0; i < field.phiCount; ++i) phis[i] = -kPi / 2 + (i + 0.5) * kPi / field.phiCount;
  for (int j = 0; j < field.tCount; ++j) ts[j] = -kPi + (j + 0.5) * 2 * kPi / field.tCount;
  const std::vector<CurvatureSample> samples = curvatureGrid(surface, phis, ts);
  const bool curvature = coloring == SphereColoring::Curvature;
  field.coloring = coloring;
  field.diverging = curvature;
  field.values.reserve(samples.size());
  field.min = INFINITY;
  field.max = -INFINITY;
  for (const CurvatureSample& s : samples) {
    const double value = curvature ? s.gaussianCurvature : s.bending;
    field.values.push_back(static_cast<float>(value));
    field.min = std::min(field.min, value);
    field.max = std::max(field.max, value);
  }
  return field;
}

// Evenly spread points (a Fibonacci lattice), each with its ellipse: the long axis along the stiffest direction,
// half-axes proportional to sqrt(S_max) and sqrt(S_min), the largest over the sphere a fixed fraction of the
// spacing so that neighbours never overlap.
std::vector<SphereEllipse> stiffnessEllipses(const ConfigurationSurface& surface) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  std::vector<CurvatureSample> samples;
  for (int k = 0; k < kStiffnessEllipses; ++k) {
    const double z = 1.0 - (k + 0.5) * 2.0 / kStiffnessEllipses;
    const double r = std::sqrt(1.0 - z * z);
    samples.push_back(surface.curvatureAt(Eigen::Vector3d(r * std::cos(golden * k), r * std::sin(golden * k), z)));
  }
  double largest = 0;
  for (const CurvatureSample& s : samples) largest = std::max(largest, std::sqrt(s.stiffnessMax));
  const double spacing = std::sqrt(4 * kPi / kStiffnessEllipses);
  const double scale = largest > 0 ? 0.42 * spacing / largest : 0.0;
  std::vector<SphereEllipse> ellipses;
  for (const CurvatureSample& s : samples) {
    const Eigen::Vector3d x = s.spherePoint.normalized();
    const Eigen::Vector3d along = (s.stiffnessDirection - s.stiffnessDirection.dot(x) * x).normalized();
    const Eigen::Vector3d across = x.cross(along);
    const Eigen::Vector3d major = along * std::sqrt(s.stiffnessMax) * scale;
    const Eigen::Vector3d minor = across * std::sqrt(std::max(s.stiffnessMin, 0.0)) * scale;
    ellipses.push_back({{x.x(), x.y(), x.z()}, {major.x(), major.y(), major.z()}, {minor.x(), minor.y(), minor.z()}});
  }
  return ellipses;
}

}  // namespace

std::shared_ptr<const SphereDecoration> makeSphereDecoration(const Chain& chain, const SphereSurfaceSpec& spec) {
  if (!spec.decorated()) return nullptr;
  const ConfigurationSurface surface(chain);
  auto decoration = std::make_shared<SphereDecoration>();
  if (spec.colorBy != SphereColoring::None) decoration->field = colourField(surface, spec.colorBy);
  decoration->seam = spec.seam;
  if (spec.stiffness) decoration->ellipses = stiffnessEllipses(surface);
  return decoration;
}

}  // namespace sl
