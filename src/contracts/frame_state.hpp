#pragma once
// FrameState: everything the renderer needs to draw one frame, and nothing about how it was computed.
// Produced by the frames stage (scene + runs sampled at frame times), consumed by render/.
// Units: linkage positions in rod lengths (plane coordinates, pins at (0,0) and (L,0));
// sphere-panel points are 3D points of the view (unit sphere for 4 rods, see ViewSpace).

#include <array>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contracts/values.hpp"

namespace sl {

// How configuration-space points are shown in the sphere panel.
enum class ViewSpace {
  Sphere,  // 4 rods: the point (cos phi cos t, cos phi sin t, sin phi) on S^2
  Ball,    // 5+ rods: S^(n-2) mapped into the unit ball, the start at the centre (frames/configuration_view.hpp)
  Circle   // 3 rods: (cos t, sin t, 0) on the equator
};

// One member of a run's family of geodesics (issue 15) at this frame: drawn thin, with the others.
struct MemberFrame {
  bool stopped = false;     // stopped at or before this frame's time (frozen where it stopped)
  std::vector<Vec2> hinges;  // the linkage panel's "feather": every member's chain, faint
  std::vector<Vec3> path;    // as RunFrame::path
  std::vector<double> pathTimes;
  Vec3 current;  // a point of the wavefront
};

// One run's state at this frame.
struct RunFrame {
  std::string name;  // run name from the scene
  // Labels as shown (the frames stage writes the registry's names; the renderer only displays them).
  std::string method;      // e.g. "christoffel-fd"
  ColorRGB color;          // the run's colour in every panel
  bool stopped = false;    // the run stopped at or before this frame's time
  double stopTime = 0;     // when it stopped (valid if stopped)
  std::string stopReason;  // why, e.g. "pole-fold-back" (valid if stopped)
  std::string stopWhy;     // what that means, in a sentence (the reason's meaning in contracts/registry.hpp)
  std::string stopMeasured;  // a watchdog's reading against its limit, e.g. "energy drift 2.11 > limit 1" (or empty)
  double baseLength = 3;   // L of this run's own linkage (runs may differ in L and masses, never in n)

  // Linkage panel: the n-1 interior hinges at the last valid time (frozen once stopped).
  std::vector<Vec2> hinges;
  // Fading trails of chosen hinges: trails[k] = past positions of hinge trailHinges[k], oldest first.
  std::vector<std::vector<Vec2>> trails;

  // Sphere panel: the path so far (oldest first) with the time of each point, and the current point.
  std::vector<Vec3> path;
  std::vector<double> pathTimes;
  Vec3 current;

  // Conjugate points reached so far (runs with "jacobi": true): their times and places on the sphere path.
  std::vector<double> conjugateTimes;
  std::vector<Vec3> conjugatePoints;

  // The run's family, in member order (the wavefront joins their current points in this order); empty if none.
  std::vector<MemberFrame> members;
};

// A read-only sequence of numbers a frame shows: the first `count` values of storage shared with the frames stage's
// history (append-only, so a value once shown never changes), or values of its own. A frame refers to its history
// instead of copying it, so building one costs the same at frame 10^5 as at frame 100. Writing to it (tests build
// series by hand) first gives it values of its own.
class SharedSamples {
 public:
  SharedSamples() = default;
  SharedSamples(std::vector<double> values) : own_(std::move(values)) {}  // NOLINT: implicit, series as vectors
  SharedSamples(std::initializer_list<double> values) : own_(values) {}
  // The first `count` values of `store`, which already holds them; it may grow later but never moves (its capacity
  // is reserved) nor changes a value before `count`.
  SharedSamples(std::shared_ptr<const std::vector<double>> store, std::size_t count)
      : store_(std::move(store)), shared_(store_->data()), count_(count) {}

  std::size_t size() const { return store_ ? count_ : own_.size(); }
  bool empty() const { return size() == 0; }
  const double* begin() const { return store_ ? shared_ : own_.data(); }
  const double* end() const { return begin() + size(); }
  double operator[](std::size_t i) const { return begin()[i]; }
  double back() const { return begin()[size() - 1]; }

  double& operator[](std::size_t i) { return own()[i]; }
  void push_back(double value) { own().push_back(value); }

 private:
  std::vector<double>& own() {
    if (store_) {
      own_.assign(shared_, shared_ + count_);
      store_.reset();
    }
    return own_;
  }

  std::vector<double> own_;                           // values of its own (when store_ is null)
  std::shared_ptr<const std::vector<double>> store_;  // else: the shared history
  const double* shared_ = nullptr;
  std::size_t count_ = 0;
};

// A time series for the plot panel.
struct PlotSeries {
  std::string label;
  ColorRGB color;
  SharedSamples times;
  SharedSamples values;  // non-finite or non-positive values on a log axis are skipped, never drawn
  std::vector<double> markTimes;  // times marked on the time axis (a Jacobi field's zeros: conjugate points)
  // When the run behind the line stopped, once it has (infinite while it runs): a red cross where the line ends.
  double stopTime = std::numeric_limits<double>::infinity();
};

struct PlotFrame {
  std::string title;  // e.g. "divergence |p_a - p_b|" or "relative energy error"
  bool logY = true;
  double timeMin = 0, timeMax = 1;  // the x axis spans the whole animation, so it does not jump
  // The y axis's data range over the whole animation (or the scene's y_range), so it does not jump either;
  // empty when no value of the whole animation can be drawn.
  std::optional<std::array<double, 2>> valueRange;
  std::string emptyNote;  // why the plot stays empty for the whole animation, if it does
  std::vector<PlotSeries> series;
};

// A scalar field over the sphere of ViewSpace::Sphere, sampled at the cell centres of an equirectangular grid:
// value(i, j) at phi = -pi/2 + (i + 1/2) pi / phiCount, t = -pi + (j + 1/2) 2 pi / tCount, the point
// (cos phi cos t, cos phi sin t, sin phi). The renderer colours the sphere with it and draws its colour bar.
struct SphereField {
  std::string label;       // what the colour bar says, e.g. "K, Gaussian curvature"
  bool diverging = false;  // signed: a diverging map centred at zero, each sign stretched over its own range
  int phiCount = 0, tCount = 0;
  std::vector<float> values;  // row-major [phi][t]
  double min = 0, max = 0;    // over the grid
};

// A stiffness ellipse on the sphere: the curve centre + cos(a) major + sin(a) minor, tangent at centre.
struct SphereEllipse {
  Vec3 centre, major, minor;
};

// What the sphere panel draws on and over the sphere, the same in every frame (shared, never copied).
struct SphereDecoration {
  std::optional<SphereField> field;
  std::vector<SphereEllipse> ellipses;
  std::string ellipseCaption;  // a line explaining the ellipses
};

struct FrameState {
  int index = 0;          // frame number in the whole animation
  double time = 0;        // simulation time of this frame
  double duration = 0;    // total simulated time
  std::string title;      // scene title
  int rods = 4;           // n
  ViewSpace viewSpace = ViewSpace::Sphere;
  std::vector<RunFrame> runs;
  std::vector<PlotFrame> plots;  // one per plot panel, in layout order
  std::shared_ptr<const SphereDecoration> sphereDecoration;  // null: the plain sphere
};

}  // namespace sl
