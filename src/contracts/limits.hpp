#pragma once
// What the program accepts, each bound written once: the scene loader, the command-line options and the
// stages that allocate check against these.

#include <cstddef>

namespace sl::limits {

inline constexpr int kMinImageSide = 16;
// llvmpipe allows 16384; 8192 keeps one RGBA frame under 256 MiB.
inline constexpr int kMaxImageSide = 8192;
// The least address space (ulimit -v, a batch system's memory request) a process must be allowed before it makes
// a GL context: under it Mesa's llvmpipe crashes (SIGSEGV) compiling its shaders or fails its allocations
// (measured on Debian 12: crashes from 250 to 550 MB, failed allocations to 650 MB, 720p and 4K frames drawn
// from 700 MB), so the renderer refuses with the limit named instead. Plus kGlAddressSpaceBytesPerPixel for the
// frame's own buffers.
inline constexpr double kMinGlAddressSpaceBytes = 768.0 * (1 << 20);
inline constexpr double kGlAddressSpaceBytesPerPixel = 16;
// Renderers drawing frames side by side in one render, in worker processes or on threads (one per core up to this):
// each holds an OpenGL context with its framebuffers and cached layers (about 20 bytes a pixel), and frames in flight.
inline constexpr int kMaxRenderers = 4;
// About 9 hours at 30 fps: anything longer is a typo.
inline constexpr long kMaxFrames = 1'000'000;
// A scene file is a few kilobytes; anything near this is not a scene (and is not read whole into memory).
inline constexpr std::size_t kMaxSceneBytes = 16u << 20;
// A title (and a short title) is one line of a frame, laid out on every frame: a few hundred characters at most,
// counted in code points, also once its placeholders are filled in (a 20,000-word title cost 46 s a frame).
inline constexpr int kMaxTitleCharacters = 300;
// Hinge and rod masses (relative units): beyond this the kinetic energy and the constraint solve overflow.
inline constexpr double kMaxMass = 1e6;
// The camera's orbit: 10 turns a second is already a blur.
inline constexpr double kMaxOrbitDegreesPerSecond = 3600;
inline constexpr int kMinRods = 3;
inline constexpr int kMaxRods = 12;          // the chart methods: their charts stay well conditioned up to here
inline constexpr int kMaxAmbientRods = 1000;  // the chart-free ambient method (O(n) per step)
inline constexpr int kMaxFps = 1000;
inline constexpr int kMaxPathSamplesPerFrame = 100;
// Hinge trails (view.trails): how many hinges, and how long a trail stays visible; together with kMaxFps they
// bound a run's trail memory (32 x 60 s x 1000 fps x 16 bytes = 31 MB).
inline constexpr int kMaxTrails = 32;
inline constexpr double kMaxTrailFadeSeconds = 60;
// A video may hold its first and its last frame this long (output.hold_start, output.hold_end).
inline constexpr double kMaxHoldSeconds = 60;
// A video plays the scene this many times as fast at most (output.playback_speed, --speed): 0.1 is slow motion
// by ten, 10 a twenty-second scene in two seconds.
inline constexpr double kMinPlaybackSpeed = 0.1;
inline constexpr double kMaxPlaybackSpeed = 10;
// A video's constant rate factor (output.video_crf, --crf): H.264's scale, 0 lossless to 51 (VP9's goes to 63).
inline constexpr int kMaxVideoCrf = 51;
// A run's sphere path keeps at most this many points (older ones thinned to every other), the newest
// kRecentPathPoints at full resolution: its memory is bounded whatever the duration and sampling.
inline constexpr std::size_t kMaxPathPoints = 20000;
inline constexpr std::size_t kRecentPathPoints = 2000;
// What the frames show: a plot whose every value stays at or below kRoundoffLevel (a relative energy error, a
// hinge distance in rod lengths: about 450 unit roundoffs), or an energy error of adaptive runs that stays within
// kToleranceEnergyFactor times their tolerance, says so in one line instead of drawing an axis; a push or drag
// start is marked by arrows over the first kPushShownSeconds of the motion.
inline constexpr double kRoundoffLevel = 1e-13;
inline constexpr double kToleranceEnergyFactor = 100;
inline constexpr double kPushShownSeconds = 1.5;
// A run's family: members beside the run, their spread and a cloud's perturbation size.
inline constexpr int kMaxFamilyMembers = 256;
inline constexpr double kMaxFamilySpread = 3.141592653589793;  // a fan's whole angle, a parallel family's width
inline constexpr double kMaxCloudEpsilon = 0.1;
// Samples of one run on a time grid (simulate --dt, the error grids of bench and stability): 5e6 rows of
// trajectory CSV are about a gigabyte.
inline constexpr long kMaxSamplesPerRun = 5'000'000;
// Adaptive integrators' relative and absolute tolerance (below 1e-16 is below double precision).
inline constexpr double kMinTolerance = 1e-16;
inline constexpr double kMaxTolerance = 1e-1;
inline constexpr double kMinFieldOfViewDegrees = 5;
inline constexpr double kMaxFieldOfViewDegrees = 120;
// The work a scene asks for is bounded before any is done (src/scene/scene_cost.cpp), in units of one hinge
// carried through one integration step. One step of a run costs (n-1) units, or (n-1) (1 + f)^2 with its f = n-3
// Jacobi fields (the fields' Gram matrix and its eigen decomposition at every step). Signals are asked between
// steps, so one step must stay well below a second: at most kMaxStepWork units (Jacobi fields on up to 250
// rods; plain runs on any chain). A scene's whole work counts every run and family member for every sphere-path
// sample (frames x view.path_samples_per_frame): at most kMaxSceneWork units, about a day of one core.
inline constexpr double kMaxStepWork = 1.6e7;
// How far a run's hinges travel in the scene's duration, in rod lengths (mass-weighted RMS; a geodesic keeps its
// speed): an integrator takes a few steps per rod length of travel at the default tolerances, so well beyond this a
// run would end on its step watchdog (RunConfig::maxSteps, 5e7) instead of its duration.
inline constexpr double kMaxHingeTravel = 1e6;
inline constexpr double kMaxSceneWork = 1e13;
// How long a render waits for a lock another process holds on its output folder before giving up (a process
// stopped with SIGSTOP, or hung, holds it for ever); it says what it waits for after the first second.
inline constexpr double kMaxLockWaitSeconds = 60;
// How long the video encoder may read nothing of a frame before the render gives up on it (an encoder stopped
// or hung); it says what it waits for after the first second. LINKAGE_ENCODER_WAIT (seconds) overrides it.
inline constexpr double kMaxEncoderStallSeconds = 60;
// The longest of those two waits the environment may ask for (LINKAGE_LOCK_WAIT, LINKAGE_ENCODER_WAIT): a week.
// Beyond, a deadline of steady_clock overflows, and a wait that long is a typo, not a choice.
inline constexpr double kMaxEnvironmentWaitSeconds = 7 * 24 * 3600;
// `connect` (src/inverse): sparse KKT systems, one exact shooting derivative per Newton solve then Broyden's
// updates, route 2 and the Morse index O(n) per node but the dense d x d blocks of the index O(n^3). Measured
// (bench/README.md, "Inverse problems"): 100 rods in about 15 s, 200 rods in about 2 minutes, growing like
// n^2.5-n^3; beyond 200 one `connect` would take a quarter of an hour and more.
inline constexpr int kMaxConnectRods = 200;
// A scene's start may name a found motion (initial.connect, initial.periodic): its index in the list, and the
// longest motion the search looks for (the commands' --max-length bounds).
inline constexpr int kMaxMotionIndex = 99;
inline constexpr double kMaxConnectLength = 1000;
inline constexpr double kMaxPeriodicLength = 200;
// The closed-geodesic search integrates explicitly: with hinge masses r apart (the kinetic mass matrix's
// condition number) the light hinge swings sqrt(r) times faster than the heavy one moves, and each ray costs
// sqrt(r) times more steps. Measured (docs/hardening.md, principle 22b): r = 1e2 about 7 s, 1e4 about 1 minute,
// 1e6 about 5 minutes, 1e12 an estimated half hour and more without one simple closed geodesic found.
inline constexpr double kMaxPeriodicMassRatio = 1e4;

}  // namespace sl::limits
