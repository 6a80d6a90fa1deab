#pragma once
// FrameState: everything the renderer needs to draw one frame, and nothing about how it was computed.
// Produced by the frames stage (scene + runs sampled at frame times), consumed by render/.
// Data only: kinds are enums of contracts/registry.hpp and readings are numbers; the words a frame shows are made
// at the rendering edge (render/frame_words.hpp). Strings here are the user's: scene title and run names.
// Units: linkage positions in rod lengths (plane coordinates, pins at (0,0) and (L,0));
// sphere-panel points are 3D points of the view (unit sphere for 4 rods, see ViewSpace).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contracts/registry.hpp"
#include "contracts/values.hpp"

namespace sl {

// How configuration-space points are shown in the sphere panel.
enum class ViewSpace {
  Sphere,  // 4 rods: the point (cos phi cos t, cos phi sin t, sin phi) on S^2
  Ball,    // 5+ rods: S^(n-2) mapped into the unit ball, the start at the centre (frames/configuration_view.hpp)
  Circle   // 3 rods: (cos t, sin t, 0) on the equator
};

// A read-only sequence a frame shows (path points, their times, plot values): `count` values of storage shared with
// the frames stage's history from `first` on, or values of its own. The history only appends to that storage and
// never moves it (a full or rewritten history goes on in new storage; frames keep the old one alive), so a value a
// frame shows never changes, and a frame refers to its history instead of copying it: building one costs the same
// at frame 10^5 as at frame 100. Writing to it (tests build frames by hand) first gives it values of its own.
template <class T>
class SharedSpan {
 public:
  SharedSpan() = default;
  SharedSpan(std::vector<T> values) : own_(std::move(values)) {}  // NOLINT: implicit, so frames can be written as vectors
  SharedSpan(std::initializer_list<T> values) : own_(values) {}
  // `count` values of `store` from `first` on, which it already holds; see above for what the store may do later.
  SharedSpan(std::shared_ptr<const std::vector<T>> store, std::size_t first, std::size_t count)
      : store_(std::move(store)), shared_(store_->data() + first), count_(count) {}

  std::size_t size() const { return store_ ? count_ : own_.size(); }
  bool empty() const { return size() == 0; }
  const T* begin() const { return store_ ? shared_ : own_.data(); }
  const T* end() const { return begin() + size(); }
  const T& operator[](std::size_t i) const { return begin()[i]; }
  const T& front() const { return begin()[0]; }
  const T& back() const { return begin()[size() - 1]; }

  T& operator[](std::size_t i) { return own()[i]; }
  void push_back(const T& value) { own().push_back(value); }
  void clear() { own().clear(); }

  friend bool operator==(const SharedSpan& a, const SharedSpan& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
  }

 private:
  std::vector<T>& own() {
    if (store_) {
      own_.assign(shared_, shared_ + count_);
      store_.reset();
    }
    return own_;
  }

  std::vector<T> own_;                           // values of its own (when store_ is null)
  std::shared_ptr<const std::vector<T>> store_;  // else: the shared history
  const T* shared_ = nullptr;
  std::size_t count_ = 0;
};

using SharedSamples = SharedSpan<double>;

// One member of a run's family of geodesics at this frame: drawn thin, with the others.
struct MemberFrame {
  bool stopped = false;     // stopped at or before this frame's time (frozen where it stopped)
  std::vector<Vec2> hinges;  // the linkage panel's "feather": every member's chain, faint
  SharedSpan<Vec3> path;    // as RunFrame::path
  SharedSamples pathTimes;
  Vec3 current;  // a point of the wavefront
};

// One run's state at this frame.
struct RunFrame {
  std::string name;  // run name from the scene
  Method method = Method::Christoffel;
  ColorRGB color;          // the run's colour in every panel
  bool stopped = false;    // the run stopped at or before this frame's time
  double stopTime = 0;     // when it stopped (valid if stopped)
  StopReason stopReason = StopReason::NonFinite;  // why (valid if stopped)
  // A watchdog's reading and its limit (energy drift, rod-length error; simulation/trajectory.hpp's StopInfo);
  // NaN where the stop has none.
  double stopMeasured = std::numeric_limits<double>::quiet_NaN();
  double stopLimit = std::numeric_limits<double>::quiet_NaN();
  double baseLength = 3;   // L of this run's own linkage (runs may differ in L and masses, never in n)
  // The linkage panel's physics: M_1..M_(n-1) at the hinges and m_1..m_n along the rods of this run's chain
  // (empty: the spec's unit hinge masses and massless rods).
  std::vector<double> hingeMasses, rodMasses;
  // A push or drag start, marked in the first frames: the start velocity of each hinge it sets moving (rod lengths
  // per second), and how strongly this frame shows them (1 at the start, fading to 0 in limits::kPushShownSeconds).
  struct HingeArrow {
    int hinge = 1;  // 1..n-1
    Vec2 velocity;
  };
  std::vector<HingeArrow> push;
  float pushShown = 0;

  // Linkage panel: the n-1 interior hinges at the last valid time (frozen once stopped).
  std::vector<Vec2> hinges;
  // Fading trails of chosen hinges: trails[k] = past positions of hinge trailHinges[k], oldest first.
  std::vector<SharedSpan<Vec2>> trails;

  // Sphere panel: the path so far (oldest first) with the time of each point, and the current point.
  SharedSpan<Vec3> path;
  SharedSamples pathTimes;
  Vec3 current;

  // Conjugate points reached so far (runs with "jacobi": true): their times and places on the sphere path.
  std::vector<double> conjugateTimes;
  std::vector<Vec3> conjugatePoints;

  // The run's family, in member order (the wavefront joins their current points in this order); empty if none.
  std::vector<MemberFrame> members;
};

// A time series for the plot panel.
struct PlotSeries {
  std::string label;  // the run's name (user data)
  ColorRGB color;
  SharedSamples times;
  SharedSamples values;  // non-finite or non-positive values on a log axis are skipped, never drawn
  std::vector<double> markTimes;  // times marked on the time axis (a Jacobi field's zeros: conjugate points)
  // When the run behind the line stopped, once it has (infinite while it runs): a red cross where the line ends.
  double stopTime = std::numeric_limits<double>::infinity();
};

// A run that stopped at its first frame, which is why a plot may stay empty.
struct EarlyStop {
  std::string run;  // its name
  double time = 0;
  StopReason reason = StopReason::NonFinite;
};

// Why a plot stays empty for the whole animation.
enum class PlotEmptiness {
  HasValues,       // not empty
  RunsStopped,     // runs stopped at once (PlotFrame::earlyStops says which)
  ZeroOnLogAxis,   // every value is 0, which a log axis cannot show
  NothingToPlot    // no value at all
};

struct PlotFrame {
  PlotKind kind = PlotKind::EnergyError;  // what it shows (its title follows from it)
  std::string referenceRun;               // a divergence plot's: the run the others are measured from
  bool logY = true;
  double timeMin = 0, timeMax = 1;  // the x axis spans the whole animation, so it does not jump
  // The y axis's data range over the whole animation (or the scene's y_range), so it does not jump either;
  // empty when no value of the whole animation can be drawn.
  std::optional<std::array<double, 2>> valueRange;
  PlotEmptiness emptiness = PlotEmptiness::HasValues;  // why the plot stays empty for the whole animation, if it does
  std::vector<EarlyStop> earlyStops;                    // with PlotEmptiness::RunsStopped
  // Set when every value of the whole animation lies within roundoff (or, for an energy error of adaptive runs,
  // within what their tolerance allows): the panel says so in one line instead of an axis.
  struct RoundoffOnly {
    double largest = 0;        // the largest |value| over the runs (0: exactly)
    bool byTolerance = false;  // above limits::kRoundoffLevel, within the level the tolerance allows
    std::size_t runs = 1;      // runs shown
  };
  std::optional<RoundoffOnly> roundoff;
  std::vector<PlotSeries> series;
};

// A scalar field over the sphere of ViewSpace::Sphere, sampled at the cell centres of an equirectangular grid:
// value(i, j) at phi = -pi/2 + (i + 1/2) pi / phiCount, t = -pi + (j + 1/2) 2 pi / tCount, the point
// (cos phi cos t, cos phi sin t, sin phi). The renderer colours the sphere with it and draws its colour bar.
struct SphereField {
  SphereColoring coloring = SphereColoring::Curvature;  // what it is (the colour bar's caption follows from it)
  bool diverging = false;  // signed: a diverging map centred at zero, each sign stretched over its own range
  int phiCount = 0, tCount = 0;
  std::vector<float> values;  // row-major [phi][t]
  double min = 0, max = 0;    // over the grid
};

// A stiffness ellipse on the sphere: the curve centre + cos(a) major + sin(a) minor, tangent at centre.
struct SphereEllipse {
  Vec3 centre, major, minor;
};

// A curve drawn on the sphere (unit-sphere points in order), named by what it is.
enum class SphereCurveKind {
  ConjugateLocus,  // where the geodesics from the distance colouring's point first focus (a caustic)
  CutLocus,        // where they stop being shortest: the ridge of the distance, a tree
  ClosedGeodesic   // a simple closed geodesic (view.sphere.closed_geodesics)
};
struct SphereCurve {
  SphereCurveKind kind = SphereCurveKind::ConjugateLocus;
  std::vector<Vec3> points;
};

// The distance colouring's point and what the distance map found (inverse/distance_map.hpp).
struct SphereDistance {
  Vec3 point;                  // on the unit sphere
  bool fromStart = true;       // the first run's start (else a configuration the scene names: marked)
  double injectivityRadius = 0;
};

// A tangent vector parallel transported round a geodesic polygon (view.sphere.holonomy; inverse/holonomy.hpp),
// carried over the whole animation: every side at once, at the fraction time / duration of its own time, each from
// the vector the side before brings to its first corner. A scene whose runs are the sides, timed to arrive together
// at the end (scenes/holonomy.json), shows each vector riding its run's ball; at the end the last side brings the
// vector back to the first corner, turned by the holonomy.
struct SphereTransport {
  // The returning vector's colour, and the holonomy plot's line (the value it reaches is that vector's turn).
  static constexpr ColorRGB kReturningColor{0.45f, 0.16f, 0.62f};
  struct Arrow {
    Vec3 base;       // on the unit sphere
    Vec3 direction;  // the transported vector there, tangent, unit length in R^3 (its angle to the sides is the
                     // kinetic metric's, drawn in the sphere's own)
    std::size_t side = 0;
    double fraction = 0;  // of the side's time, from its first corner
    double swept = 0;     // integral of K dA swept from the loop's apex by the side so far (Holonomy::Sample::swept)
  };
  std::vector<Arrow> arrows;  // side by side, each at fractions 0, 1/k, ..., 1 (k = samplesPerSide)
  int samplesPerSide = 1;
  std::vector<Vec3> corners;
  double holonomy = 0;           // the turning, in (-pi, pi]
  double angleExcess = 0;        // 2 pi - sum of the turning angles at the corners (angle sum - pi for a triangle)
  double enclosedCurvature = 0;  // integral of K dA over the region to the loop's left

  // How far round the sides are at `time` of an animation of this `duration`: every side is carried over the whole
  // animation, so the fraction of each side's time is time / duration, in [0, 1].
  static double carriedFraction(double time, double duration) {
    return duration > 0 ? std::clamp(time / duration, 0.0, 1.0) : 1.0;
  }
  // Side `side`'s carried vector at `fraction` of its time in [0, 1], between the two samples around it.
  Arrow carriedAt(std::size_t side, double fraction) const {
    const double at = std::clamp(fraction, 0.0, 1.0) * samplesPerSide;
    const std::size_t k = std::min(static_cast<std::size_t>(at), static_cast<std::size_t>(samplesPerSide - 1));
    const Arrow& a = arrows.at(side * std::size_t(samplesPerSide + 1) + k);
    const Arrow& b = arrows.at(side * std::size_t(samplesPerSide + 1) + k + 1);
    const double u = at - double(k);
    const auto mix = [u](const Vec3& p, const Vec3& q) {
      return Vec3{(1 - u) * p.x + u * q.x, (1 - u) * p.y + u * q.y, (1 - u) * p.z + u * q.z};
    };
    const auto unit = [](Vec3 v) {
      const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
      return Vec3{v.x / n, v.y / n, v.z / n};
    };
    Arrow c = a;
    c.base = unit(mix(a.base, b.base));
    Vec3 d = mix(a.direction, b.direction);  // tangent again at the base
    const double along = d.x * c.base.x + d.y * c.base.y + d.z * c.base.z;
    c.direction = unit({d.x - along * c.base.x, d.y - along * c.base.y, d.z - along * c.base.z});
    c.fraction = std::clamp(fraction, 0.0, 1.0);
    c.swept = (1 - u) * a.swept + u * b.swept;
    return c;
  }
  // The curvature the sides have swept by `fraction` of their time, together: at 1, enclosedCurvature.
  double sweptAt(double fraction) const {
    double total = 0;
    for (std::size_t side = 0; side < corners.size(); ++side) total += carriedAt(side, fraction).swept;
    return total;
  }
};

// What the sphere panel draws on and over the sphere, the same in every frame (shared, never copied).
struct SphereDecoration {
  std::optional<SphereField> field;
  std::vector<SphereEllipse> ellipses;  // stiffness glyphs (geometry/curvature.hpp), explained below the sphere
  bool seam = false;                    // the seams t = +-pi/2 drawn and named
  std::optional<SphereDistance> distance;  // with the distance colouring
  std::vector<SphereCurve> curves;      // the loci of the distance colouring, each named by a label
  std::optional<SphereTransport> transport;  // a vector carried round a polygon, with its holonomy
};

struct FrameState {
  int index = 0;          // frame number in the whole animation
  double time = 0;        // simulation time of this frame
  double duration = 0;    // total simulated time
  std::string title;      // scene title
  std::string shortTitle;  // the scene's short title, for frames too narrow for the title (empty: none)
  int rods = 4;           // n
  ViewSpace viewSpace = ViewSpace::Sphere;
  std::vector<RunFrame> runs;
  std::vector<PlotFrame> plots;  // one per plot panel, in layout order
  std::shared_ptr<const SphereDecoration> sphereDecoration;  // null: the plain sphere
  // The part of the plane the linkage panel shows, in rod lengths {x0, x1, y0, y1}: both pins and every hinge of
  // every run at every frame time of the whole animation; empty: every configuration the chains can take.
  std::optional<std::array<double, 4>> linkageBox;
  // The sphere panel's camera in this frame, from the sphere's centre towards the eye (unit length), when the frames
  // stage directs it (CameraMode::Directed); empty: the scene's fixed or orbiting camera.
  std::optional<Vec3> cameraDirection;
};

}  // namespace sl
