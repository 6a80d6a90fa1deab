#pragma once
// A scene: everything one animation computes (scenes/README.md documents every key).
// Loaded and validated by loadScene (scene_loader.hpp); nothing else decides what is computed.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "linkage/chain.hpp"
#include "render/renderer.hpp"
#include "simulation/trajectory.hpp"

namespace sl {

// The start of the motion as the scene states it; initial_state.hpp turns it into an InitialState.
struct InitialSpec {
  enum class Kind { ChartCoordinates, Drag };
  Kind kind = Kind::ChartCoordinates;
  Eigen::VectorXd coords;         // chart 0 coordinates, outermost first ((phi, t) for 4 rods)
  Eigen::VectorXd velocity;       // their rates
  Eigen::VectorXd dragPoint;      // a point of R^(n-1), normalised onto S^(n-2)
  Eigen::VectorXd dragDirection;  // projected onto the tangent space at dragPoint
  bool unitSpeed = false;         // rescale the velocity so that g(v, v) = 1
};

struct RunSpec {
  std::string name;
  RunConfig config;
  std::optional<ColorRGB> color;  // default: a palette colour by position
};

enum class PlotKind { Divergence, EnergyError };

// One plot panel: what it shows and how.
struct PlotSpec {
  PlotKind kind = PlotKind::Divergence;
  bool logY = true;
};

struct OutputSpec {
  int fps = 30;
  int width = 1280, height = 720;
  std::string folder;  // default renders/<name>, relative to the working directory
  bool png = true;     // write PNG frames
  std::string video;   // an mp4 path, empty = no video
};

struct ViewSpec {
  RenderSettings render;         // panels, camera, linkage layout, fades (width/height from output)
  std::vector<PlotSpec> plots;   // one per Plot panel, in layout order (PanelSpec::plotIndex)
  std::vector<int> trailHinges;  // 1-based hinge numbers with fading trails
  int pathSamplesPerFrame = 4;   // sphere-path points recorded per frame interval
};

struct Scene {
  std::string file;  // where it was loaded from (for messages)
  std::string name;  // also the default output folder name
  std::string title;
  Chain chain;
  InitialSpec initial;
  double duration = 20;
  std::vector<RunSpec> runs;
  OutputSpec output;
  ViewSpec view;

  // Frames k = 0..ceil(duration * fps), at times k / fps.
  int frameCount() const;
  double frameTime(int frame) const { return frame / static_cast<double>(output.fps); }
};

}  // namespace sl
