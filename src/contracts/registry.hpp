#pragma once
// The kinds the program knows, each with its name (as written in scene files, CSVs and messages) and its
// properties, written once. Names are parsed into enums at the boundary (scene loader, command-line options);
// everything downstream switches on the enum. Tests, the fuzzer's dictionary and the docs read these tables.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sl {

// A kind with its name; the tables below are arrays of these, in the order help texts list them.
template <class Kind>
struct Named {
  Kind kind;
  std::string_view name;
};

// === Geodesic methods (docs/methods.md)

enum class Method { ChristoffelFd, EmbeddedFd, Christoffel, Embedded, Ambient };

struct MethodTraits {
  Method kind;
  std::string_view name;
  // The spec's formulas as published (sections 4 and 5): 4 rods, unit hinge masses, massless rods only.
  bool published;
  // Integrated in chart coordinates (the others: chart-free, hinge positions under rod constraints).
  bool chartBased;
  // Switches to another chart of the atlas near a pole (the published methods stay in the spec's chart).
  bool usesAtlas;
  std::string_view description;  // one line, for `linkage list-methods`
};

inline constexpr std::array<MethodTraits, 5> kMethods{{
    {Method::ChristoffelFd, "christoffel-fd", true, true, false,
     "spec section 4 as published: Christoffel symbols by central differences; 4 rods, unit masses, one chart"},
    {Method::EmbeddedFd, "embedded-fd", true, true, false,
     "spec section 5 as published: second differences of Psi, 2x2 normal system; 4 rods, one chart"},
    {Method::Christoffel, "christoffel", false, true, true,
     "Christoffel symbols from exact metric derivatives; any n and masses; switches charts near a pole"},
    {Method::Embedded, "embedded", false, true, true,
     "normal acceleration with exact derivatives of Psi; any n and masses; switches charts near a pole"},
    {Method::Ambient, "ambient", false, false, false,
     "chart-free: the constrained system of hinge positions, O(n) per step; passes straight through the poles"},
}};

// === Integrators (Boost.Odeint; simulation/steppers.hpp)

enum class Integrator { Rk4, Dopri5, Rkf78, BulirschStoer };

struct IntegratorTraits {
  Integrator kind;
  std::string_view name;
  bool adaptive;  // takes "tolerance"; a fixed-step integrator takes "step"
  std::string_view description;  // one line, for `linkage list-methods`
};

inline constexpr std::array<IntegratorTraits, 4> kIntegrators{{
    {Integrator::Rk4, "rk4", false, "classical Runge-Kutta 4, fixed step, cubic Hermite between steps"},
    {Integrator::Dopri5, "dopri5", true, "Dormand-Prince 5(4), adaptive, dense output"},
    {Integrator::Rkf78, "rkf78", true, "Runge-Kutta-Fehlberg 7(8), adaptive"},
    {Integrator::BulirschStoer, "bulirsch-stoer", true, "Bulirsch-Stoer extrapolation, adaptive"},
}};

// === Why a run stops (the watchdogs of simulation/trajectory.cpp, and a method's own failure)

enum class StopReason {
  NonFinite,
  PoleFoldBack,
  FieldBlowUp,
  EnergyBlowUp,
  StepSizeCollapse,
  RodLength,
  MaxSteps,
  ConstraintRankLoss
};

struct StopReasonTraits {
  StopReason kind;
  std::string_view name;     // in CSV status rows, the text panel and stderr
  std::string_view meaning;  // one line for docs, help texts and the frames
};

inline constexpr std::array<StopReasonTraits, 8> kStopReasons{{
    {StopReason::NonFinite, "non-finite", "the state became NaN or infinite"},
    {StopReason::PoleFoldBack, "pole-fold-back", "a single-chart method crossed a pole of its chart"},
    {StopReason::FieldBlowUp, "field-blow-up",
     "one step moved a single-chart method's state further than any smooth motion can (its vector field blew up, "
     "as the published metric does on the seam t = +-pi/2)"},
    {StopReason::EnergyBlowUp, "energy-blow-up", "the relative energy drift passed the watchdog's limit"},
    {StopReason::StepSizeCollapse, "step-size-collapse", "the integrator's step shrank to nothing"},
    {StopReason::RodLength, "rod-length", "a rod's length drifted past the watchdog's limit"},
    {StopReason::MaxSteps, "max-steps", "the run used up its step budget"},
    {StopReason::ConstraintRankLoss, "constraint-rank-loss",
     "every rod lies on one line (the chain folded flat or stretched straight): the rod constraints lose rank and "
     "the motion is not determined there"},
}};

// === Families of geodesics from a run's start (simulation/family.hpp)

enum class FamilyKind { Fan, Parallel, Cloud };
inline constexpr std::array<Named<FamilyKind>, 3> kFamilyKinds{{
    {FamilyKind::Fan, "fan"},            // one point, directions spread by angle in a g-orthonormal frame
    {FamilyKind::Parallel, "parallel"},  // starts spaced along the geodesic orthogonal to the run's
    {FamilyKind::Cloud, "cloud"},        // random perturbations of the start, for sensitivity
}};

// === Scene view kinds (scenes/README.md)

enum class PanelKind { Linkage, Sphere, Plot, Text };
inline constexpr std::array<Named<PanelKind>, 4> kPanelKinds{{
    {PanelKind::Sphere, "sphere"},
    {PanelKind::Linkage, "linkage"},
    {PanelKind::Plot, "plot"},
    {PanelKind::Text, "text"},
}};

enum class PlotKind { Divergence, EnergyError, Jacobi, Spread, Sectional, Holonomy };
inline constexpr std::array<Named<PlotKind>, 6> kPlotKinds{{
    {PlotKind::Divergence, "divergence"},
    {PlotKind::EnergyError, "energy"},
    {PlotKind::Jacobi, "jacobi"},  // |J_perp| of the runs with "jacobi": true, their conjugate points marked
    {PlotKind::Spread, "spread"},  // how far each run's family strays from it (max hinge distance)
    // 5 rods and more: the smallest and largest curvature of the planes through each run's velocity
    {PlotKind::Sectional, "sectional"},
    // with view.sphere.holonomy: the curvature the polygon's sides have swept, rising to the holonomy
    {PlotKind::Holonomy, "holonomy"},
}};

enum class LinkageLayout { SingleRun, SideBySide, Overlay };
inline constexpr std::array<Named<LinkageLayout>, 3> kLinkageLayouts{{
    {LinkageLayout::SingleRun, "single"},
    {LinkageLayout::SideBySide, "side-by-side"},
    {LinkageLayout::Overlay, "overlay"},
}};

// The look of what is drawn on the frame's background (text, axes, labels, the floor and pins; view.theme): dark
// ink on a light page for papers and light slides, light ink on a dark page for dark slides. The sphere and the
// chain are objects lit the same way in both (render/palette.hpp).
enum class Theme { Light, Dark };
inline constexpr std::array<Named<Theme>, 2> kThemes{{
    {Theme::Light, "light"},
    {Theme::Dark, "dark"},
}};

// How the sphere panel's camera moves: facing the action and each event as it happens (frames/directed_camera.hpp
// plans it from the whole motion), from one fixed direction, or orbiting about the vertical axis at a constant rate.
enum class CameraMode { Directed, Fixed, Orbit };
inline constexpr std::array<Named<CameraMode>, 3> kCameraModes{{
    {CameraMode::Directed, "directed"},
    {CameraMode::Fixed, "fixed"},
    {CameraMode::Orbit, "orbit"},
}};

// What colours the sphere panel's sphere (4 rods; geometry/curvature.hpp computes the curvatures,
// inverse/distance_map.hpp the distance from a point).
enum class SphereColoring { None, Curvature, Bending, Distance };
inline constexpr std::array<Named<SphereColoring>, 4> kSphereColorings{{
    {SphereColoring::None, "none"},
    {SphereColoring::Curvature, "curvature"},
    {SphereColoring::Bending, "bending"},
    {SphereColoring::Distance, "distance"},
}};

// === Video formats (chosen by the video file's extension) and qualities

enum class VideoFormat { Mp4, Webm, Gif };
struct VideoFormatTraits {
  VideoFormat kind;
  std::string_view name;  // also the file extension, without the dot
  bool needsEvenSize;     // yuv420p chroma subsampling halves both sides
  std::string_view description;
};
inline constexpr std::array<VideoFormatTraits, 3> kVideoFormats{{
    {VideoFormat::Mp4, "mp4", true, "H.264, yuv420p: plays everywhere"},
    {VideoFormat::Webm, "webm", true, "VP9, yuv420p: smaller, for web pages"},
    {VideoFormat::Gif, "gif", false, "palette-optimised GIF: for slides and web pages, no player needed"},
}};

enum class VideoQuality { High, Medium, Small };
inline constexpr std::array<Named<VideoQuality>, 3> kVideoQualities{{
    {VideoQuality::High, "high"},
    {VideoQuality::Medium, "medium"},
    {VideoQuality::Small, "small"},
}};

// How PNG frames are compressed (docs/rendering.md gives the cost of each in time and bytes).
enum class PngCompression { Fast, Small };
inline constexpr std::array<Named<PngCompression>, 2> kPngCompressions{{
    {PngCompression::Fast, "fast"},    // this program's run-length deflate (output/fast_png.hpp)
    {PngCompression::Small, "small"},  // libdeflate level 1
}};

// === How frames are drawn: the OpenGL backend (docs/rendering.md, "GL backends"). Chosen per process (--gl,
// LINKAGE_GL); the software ones draw on Mesa's llvmpipe and give the same bytes.

enum class GlBackend { Auto, Egl, EglGpu, OsMesa };
struct GlBackendTraits {
  GlBackend kind;
  std::string_view name;
  bool software;  // llvmpipe: its pixels are this program's reference (a GPU's differ)
  std::string_view description;  // one line, for --help
};
inline constexpr std::array<GlBackendTraits, 4> kGlBackends{{
    {GlBackend::Auto, "auto", true, "EGL on Mesa's software device, OSMesa where EGL cannot start (the default)"},
    {GlBackend::Egl, "egl", true, "EGL without a display on Mesa's software device (llvmpipe)"},
    {GlBackend::EglGpu, "egl-gpu", false, "EGL on the first GPU device: faster, but its pixels differ from llvmpipe's"},
    {GlBackend::OsMesa, "osmesa", true, "OSMesa (llvmpipe); Mesa 25.1 and later no longer ship it"},
}};

// === What the inverse problems find (inverse/periodic.hpp, inverse/connect.hpp; docs/geometry.md)

// A closed geodesic's linear stability, from the trace of its monodromy (|tr| < 2, > 2, = 2).
enum class Stability { Elliptic, Hyperbolic, Parabolic };
inline constexpr std::array<Named<Stability>, 3> kStabilities{{
    {Stability::Elliptic, "elliptic"},
    {Stability::Hyperbolic, "hyperbolic"},
    {Stability::Parabolic, "parabolic"},
}};

// The 4-rod chain's symmetries: the mirror y -> -y, the end swap p_k -> (L - x, y) of p_(n-k), the half turn
// p_k -> (L, 0) - p_(n-k) (the last two isometries only for masses symmetric end for end).
enum class ChainSymmetry { Mirror, EndSwap, HalfTurn };
inline constexpr std::array<Named<ChainSymmetry>, 3> kChainSymmetries{{
    {ChainSymmetry::Mirror, "mirror"},
    {ChainSymmetry::EndSwap, "end swap"},
    {ChainSymmetry::HalfTurn, "half turn"},
}};

// Where a discrete geodesic (route 2) started: a great-circle arc of the sphere between the end points (the short
// or the long way), or route 1's shot path.
enum class DiscreteSeed { SphereArc, SphereArcLongWay, ShootingPath };
inline constexpr std::array<Named<DiscreteSeed>, 3> kDiscreteSeeds{{
    {DiscreteSeed::SphereArc, "sphere arc"},
    {DiscreteSeed::SphereArcLongWay, "sphere arc, long way"},
    {DiscreteSeed::ShootingPath, "shooting path"},
}};

// === Look-ups, the same for every table

template <class Table>
constexpr const auto& traitsOf(const Table& table, decltype(table[0].kind) kind) {
  for (const auto& entry : table)
    if (entry.kind == kind) return entry;
  return table[0];  // unreachable for a complete table (tests/contracts check completeness)
}

template <class Table>
constexpr std::optional<decltype(std::declval<Table>()[0].kind)> parseKind(const Table& table, std::string_view name) {
  for (const auto& entry : table)
    if (entry.name == name) return entry.kind;
  return std::nullopt;
}

template <class Table>
std::vector<std::string> namesOf(const Table& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.name);
  return names;
}

// Every kind of a table, in the table's order (e.g. a sweep's default: all methods).
template <class Table>
auto kindsOf(const Table& table) {
  std::vector<std::remove_cvref_t<decltype(table[0].kind)>> kinds;
  for (const auto& entry : table) kinds.push_back(entry.kind);
  return kinds;
}

inline const MethodTraits& traits(Method m) { return traitsOf(kMethods, m); }
inline const IntegratorTraits& traits(Integrator i) { return traitsOf(kIntegrators, i); }
inline const StopReasonTraits& traits(StopReason r) { return traitsOf(kStopReasons, r); }

inline const VideoFormatTraits& traits(VideoFormat f) { return traitsOf(kVideoFormats, f); }
inline const GlBackendTraits& traits(GlBackend b) { return traitsOf(kGlBackends, b); }

// The format a video path asks for by its extension (".mp4", ".webm", ".gif"; case-insensitive), if any.
inline std::optional<VideoFormat> videoFormatOfPath(std::string_view path) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return std::nullopt;
  std::string extension(path.substr(dot + 1));
  for (char& c : extension) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return parseKind(kVideoFormats, extension);
}

inline std::string nameOf(Method m) { return std::string(traits(m).name); }
inline std::string nameOf(Integrator i) { return std::string(traits(i).name); }
inline std::string nameOf(StopReason r) { return std::string(traits(r).name); }
inline std::string nameOf(GlBackend b) { return std::string(traits(b).name); }
inline std::string nameOf(Stability s) { return std::string(traitsOf(kStabilities, s).name); }
inline std::string nameOf(ChainSymmetry s) { return std::string(traitsOf(kChainSymmetries, s).name); }
inline std::string nameOf(DiscreteSeed s) { return std::string(traitsOf(kDiscreteSeeds, s).name); }

}  // namespace sl
