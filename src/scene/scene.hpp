#pragma once
// A scene: everything one animation computes (scenes/README.md documents every key).
// Loaded and validated by loadScene (scene_loader.hpp); nothing else decides what is computed.

#include <optional>
#include <string>
#include <vector>

#include "contracts/output_settings.hpp"
#include "contracts/run_config.hpp"
#include "contracts/time_grid.hpp"
#include "contracts/values.hpp"
#include "contracts/view_settings.hpp"
#include "linkage/chain.hpp"

namespace sl {

struct RunSpec {
  std::string name;
  RunConfig config;
  // The run's physics and start: the scene's "linkage" and "initial" unless the run gives its own (the number
  // of rods is always the scene's).
  Chain chain;
  InitialSpec initial;
  bool ownLinkage = false;  // the run gave "linkage" / "initial" (messages name runs[i].linkage ...)
  bool ownInitial = false;
  std::optional<ColorRGB> color;  // default: a palette colour by position
  std::optional<FamilySpec> family;  // geodesics around the run, drawn beside it
};

struct Scene {
  std::string file;  // where it was loaded from (for messages)
  // What identifies the scene as given: the file's text as read (once: it may be a pipe) and the --set
  // overrides. Renders record its hash, so shards and resumes join only the same scene.
  std::string identity;
  std::string name;  // also the default output folder name
  std::string title;
  std::string shortTitle;  // shown where the title does not fit (small frames); empty: the title, cut at a word
  Chain chain;          // the runs' default linkage; n is every run's
  InitialSpec initial;  // the runs' default start
  double duration = 20;
  // "duration" was left out (every run starts from a found motion): the commands set it to the longest motion's
  // time when they resolve the starts (cli/motion_starts.hpp).
  bool durationFromMotions = false;
  std::vector<RunSpec> runs;
  OutputSettings output;
  ViewSettings view;
  // view.sphere.distance_from: the configuration the distance colouring is measured from as the scene names it
  // (empty: the first run's start); the commands resolve it into its sphere point (cli/motion_starts.hpp).
  std::optional<ConfigurationSpec> distanceFrom;
  Eigen::VectorXd distancePoint;
  // view.sphere.holonomy.corners as the scene names them, and their sphere points once the commands resolve them
  // (cli/motion_starts.hpp): the geodesic polygon whose holonomy the sphere panel draws.
  std::vector<ConfigurationSpec> holonomyCorners;
  std::vector<Eigen::VectorXd> holonomyPoints;

  int frameCount() const { return static_cast<int>(sl::frameCount(duration, output.fps)); }
  double frameTime(int frame) const { return sl::frameTime(frame, output.fps); }
};

}  // namespace sl
