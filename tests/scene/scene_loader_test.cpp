// Loading good scenes: every key lands where the rest of the program reads it.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contracts/limits.hpp"
#include "contracts/registry.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

using testing::shippedScene;

const char* kFullScene = R"({
  "name": "full", "title": "All keys",
  "linkage": { "rods": 5, "L": 4.2, "hinge_masses": [1, 2, 3, 4], "rod_masses": [0.5, 0, 0, 1, 0] },
  "initial": { "coords": [0.1, 0.2, 0.3], "velocity": [1, 2, 3], "unit_speed": true },
  "duration": 2.5,
  "runs": [ { "name": "x", "method": "embedded", "integrator": "dopri5", "tolerance": 1e-9, "color": [1, 0, 0.5],
              "watchdog": { "max_energy_drift": 0.1, "max_rod_length_error": 1e-4, "max_steps": 1000 } },
            { "name": "y", "method": "ambient", "integrator": "rk4", "step": 0.05 } ],
  "output": { "fps": 24, "width": 640, "height": 360, "folder": "somewhere", "png": false, "video": "v.mp4" },
  "view": { "panels": ["linkage", { "panel": "plot", "plot": "energy", "scale": "linear", "rect": [0, 0.5, 1, 0.5] },
                       { "panel": "plot" }],
            "camera": { "direction": [0, 0, 1], "orbit_degrees_per_second": 5, "field_of_view": 40 },
            "linkage_layout": "side-by-side", "linkage_run": "y", "trails": [1, 4],
            "trail_fade_seconds": 3, "path_fade_seconds": 4, "path_samples_per_frame": 2,
            "background": [0, 0, 0], "antialias": false }
})";

TEST(SceneLoader, EveryKeyIsRead) {
  const Scene scene = parseScene(kFullScene, "full.json");
  EXPECT_EQ(scene.name, "full");
  EXPECT_EQ(scene.title, "All keys");
  EXPECT_EQ(scene.chain.rods, 5);
  EXPECT_DOUBLE_EQ(scene.chain.baseLength, 4.2);
  EXPECT_DOUBLE_EQ(scene.chain.hingeMasses(3), 4);
  EXPECT_DOUBLE_EQ(scene.chain.rodMasses(0), 0.5);
  EXPECT_TRUE(scene.initial.unitSpeed);
  EXPECT_DOUBLE_EQ(scene.initial.velocity(2), 3);
  EXPECT_DOUBLE_EQ(scene.duration, 2.5);
  ASSERT_EQ(scene.runs.size(), 2u);
  EXPECT_EQ(scene.runs[0].config.method, Method::Embedded);
  EXPECT_EQ(scene.runs[0].config.integrator, Integrator::Dopri5);
  EXPECT_DOUBLE_EQ(scene.runs[0].config.tolerance, 1e-9);
  EXPECT_DOUBLE_EQ(scene.runs[0].config.maxRelativeEnergyDrift, 0.1);
  EXPECT_DOUBLE_EQ(scene.runs[0].config.maxRodLengthError, 1e-4);
  EXPECT_EQ(scene.runs[0].config.maxSteps, 1000);
  EXPECT_FLOAT_EQ(scene.runs[0].color->b, 0.5f);
  EXPECT_DOUBLE_EQ(scene.runs[1].config.step, 0.05);
  EXPECT_EQ(scene.runs[1].config.method, Method::Ambient);
  EXPECT_EQ(scene.runs[1].config.integrator, Integrator::Rk4);
  EXPECT_EQ(scene.output.fps, 24);
  EXPECT_EQ(scene.output.folder, "somewhere");
  EXPECT_FALSE(scene.output.png);
  EXPECT_EQ(scene.output.video, "v.mp4");
  EXPECT_EQ(scene.output.size.width, 640);
  EXPECT_EQ(scene.output.size.height, 360);
  const ViewSettings& view = scene.view;
  ASSERT_EQ(view.panels.size(), 3u);
  EXPECT_EQ(view.panels[1].kind, PanelKind::Plot);
  EXPECT_EQ(view.panels[2].plotIndex, 1);
  ASSERT_TRUE(view.panels[1].rect.has_value());
  EXPECT_DOUBLE_EQ((*view.panels[1].rect)[1], 0.5);
  ASSERT_EQ(view.plots.size(), 2u);
  EXPECT_EQ(view.plots[0].kind, PlotKind::EnergyError);
  EXPECT_FALSE(view.plots[0].logY);
  EXPECT_EQ(view.plots[1].kind, PlotKind::Divergence);  // two runs: divergence by default
  EXPECT_DOUBLE_EQ(view.camera.viewDirection.z, 1);
  EXPECT_DOUBLE_EQ(view.camera.orbitDegreesPerSecond, 5);
  EXPECT_DOUBLE_EQ(view.camera.fieldOfViewDegrees, 40);
  EXPECT_EQ(view.linkageLayout, LinkageLayout::SideBySide);
  EXPECT_EQ(view.linkageRun, 1);
  EXPECT_EQ(view.trailHinges, (std::vector<int>{1, 4}));
  EXPECT_DOUBLE_EQ(view.trailFadeSeconds, 3);
  EXPECT_DOUBLE_EQ(view.pathFadeSeconds, 4);
  EXPECT_EQ(view.pathSamplesPerFrame, 2);
  EXPECT_FLOAT_EQ(view.background.r, 0);
  EXPECT_FALSE(view.antialias);
}

TEST(SceneLoader, DefaultsFillWhatIsLeftOut) {
  const Scene scene = parseScene(R"({"name": "d", "linkage": {"rods": 4, "L": 3},
      "initial": {"coords": [0, 0], "velocity": [1, 0]}, "duration": 1, "runs": [{"name": "r"}]})",
                                 "d.json");
  EXPECT_EQ(scene.chain.hingeMasses, Eigen::VectorXd::Ones(3));
  EXPECT_EQ(scene.chain.rodMasses, Eigen::VectorXd::Zero(4));
  EXPECT_EQ(scene.runs[0].config.method, RunConfig{}.method);
  EXPECT_EQ(scene.output.folder, "renders/d");
  EXPECT_EQ(scene.output.fps, 30);
  EXPECT_EQ(scene.output.size.width, 1280);
  ASSERT_EQ(scene.view.panels.size(), 2u);
  EXPECT_EQ(scene.view.panels[0].kind, PanelKind::Sphere);
  EXPECT_EQ(scene.view.panels[1].kind, PanelKind::Linkage);
}

// A theme sets the page the frame is drawn on; a background the scene gives wins over it, whichever comes first.
TEST(SceneLoader, ThemeSetsTheBackgroundUnlessTheSceneGivesOne) {
  const auto viewOf = [](const std::string& view) {
    return parseScene(
               R"({"name": "d", "linkage": {"rods": 4, "L": 3}, "initial": {"coords": [0, 0], "velocity": [1, 0]},
        "duration": 1, "runs": [{"name": "r"}], "view": )" +
                   view + "}",
               "d.json")
        .view;
  };
  EXPECT_EQ(viewOf("{}").theme, Theme::Light);
  EXPECT_EQ(viewOf("{}").background, themeBackground(Theme::Light));
  const ViewSettings dark = viewOf(R"({"theme": "dark"})");
  EXPECT_EQ(dark.theme, Theme::Dark);
  EXPECT_EQ(dark.background, themeBackground(Theme::Dark));
  EXPECT_NE(themeBackground(Theme::Dark), themeBackground(Theme::Light));
  for (const char* view :
       {R"({"theme": "dark", "background": [0, 0, 0.5]})", R"({"background": [0, 0, 0.5], "theme": "dark"})"}) {
    const ViewSettings own = viewOf(view);
    EXPECT_EQ(own.theme, Theme::Dark);
    EXPECT_EQ(own.background, (ColorRGB{0, 0, 0.5f})) << view;
  }
}

// The camera's mode: as asked; else a scene that fixes a direction or an orbit keeps it, the rest are directed. A mode
// that contradicts the orbit rate is refused, naming the key.
TEST(SceneLoader, CameraModeFollowsWhatTheSceneFixes) {
  const auto modeOf = [](const std::string& camera) {
    const std::string view = camera.empty() ? "" : R"(, "view": {"camera": )" + camera + "}";
    return parseScene(R"({"name": "d", "linkage": {"rods": 4, "L": 3}, "initial": {"coords": [0, 0], "velocity": [1, 0]},
        "duration": 1, "runs": [{"name": "r"}])" + view + "}", "d.json").view.camera.mode;
  };
  EXPECT_EQ(modeOf(""), CameraMode::Directed);
  EXPECT_EQ(modeOf(R"({"field_of_view": 40})"), CameraMode::Directed);
  EXPECT_EQ(modeOf(R"({"direction": [0, 1, 0]})"), CameraMode::Fixed);
  EXPECT_EQ(modeOf(R"({"direction": [0, 1, 0], "orbit_degrees_per_second": 5})"), CameraMode::Orbit);
  EXPECT_EQ(modeOf(R"({"orbit_degrees_per_second": 5})"), CameraMode::Orbit);
  EXPECT_EQ(modeOf(R"({"direction": [0, 1, 0], "mode": "directed"})"), CameraMode::Directed);
  EXPECT_EQ(modeOf(R"({"mode": "fixed"})"), CameraMode::Fixed);
  for (const auto& [camera, path] : std::vector<std::pair<std::string, std::string>>{
           {R"({"mode": "orbit"})", "view.camera.mode"},
           {R"({"mode": "directed", "orbit_degrees_per_second": 5})", "view.camera.orbit_degrees_per_second"},
           {R"({"mode": "sideways"})", "view.camera.mode"}}) {
    SCOPED_TRACE(camera);
    try {
      modeOf(camera);
      ADD_FAILURE() << "accepted";
    } catch (const SceneError& error) {
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
  }
}

// Every method and integrator of the registry is accepted under its name, with the accuracy key its
// integrator takes (the published methods need 4 rods, as here).
TEST(SceneLoader, AcceptsEveryRegisteredMethodAndIntegrator) {
  std::string runs;
  for (const MethodTraits& method : kMethods) {
    for (const IntegratorTraits& integrator : kIntegrators) {
      runs += std::string(runs.empty() ? "" : ", ") + "{\"name\": \"" + std::string(method.name) + " " +
              std::string(integrator.name) + "\", \"method\": \"" + std::string(method.name) +
              "\", \"integrator\": \"" + std::string(integrator.name) + "\", " +
              (integrator.adaptive ? "\"tolerance\": 1e-9}" : "\"step\": 0.01}");
    }
  }
  const Scene scene = parseScene(R"({"name": "every", "linkage": {"rods": 4, "L": 3},
      "initial": {"coords": [0, 0], "velocity": [1, 0]}, "duration": 1, "runs": [)" +
                                     runs + "]}",
                                 "every.json");
  ASSERT_EQ(scene.runs.size(), kMethods.size() * kIntegrators.size());
  size_t i = 0;
  for (const MethodTraits& method : kMethods) {
    for (const IntegratorTraits& integrator : kIntegrators) {
      SCOPED_TRACE(scene.runs[i].name);
      EXPECT_EQ(scene.runs[i].config.method, method.kind);
      EXPECT_EQ(scene.runs[i].config.integrator, integrator.kind);
      ++i;
    }
  }
}

// One bound on the frame size for scenes and --size: limits::kMaxImageSide, inclusive.
TEST(SceneLoader, ImageSizeBounds) {
  EXPECT_TRUE(checkImageSize({limits::kMaxImageSide, limits::kMaxImageSide}, true, "output").empty());
  EXPECT_TRUE(checkImageSize({limits::kMinImageSide, limits::kMinImageSide}, false, "output").empty());
  const std::vector<SceneProblem> wide = checkImageSize({limits::kMaxImageSide + 1, 90}, false, "output");
  ASSERT_EQ(wide.size(), 1u);
  EXPECT_EQ(wide[0].jsonPath, "output.width");
  EXPECT_NE(wide[0].message.find("found " + std::to_string(limits::kMaxImageSide + 1)), std::string::npos)
      << wide[0].message;
  const std::vector<SceneProblem> low = checkImageSize({160, limits::kMinImageSide - 1}, false, "output");
  ASSERT_EQ(low.size(), 1u);
  EXPECT_EQ(low[0].jsonPath, "output.height");
  const std::vector<SceneProblem> odd = checkImageSize({161, 90}, true, "output");
  ASSERT_EQ(odd.size(), 1u);
  EXPECT_EQ(odd[0].jsonPath, "output.width");
  EXPECT_TRUE(checkImageSize({161, 90}, false, "output").empty()) << "odd sizes are fine without a video";
}

TEST(SceneLoader, FrameCountCoversTheDurationWithBothEnds) {
  Scene scene;
  scene.duration = 20;
  scene.output.fps = 30;
  EXPECT_EQ(scene.frameCount(), 601);  // k = 0..600
  scene.duration = 0.95;
  scene.output.fps = 10;
  EXPECT_EQ(scene.frameCount(), 11);  // ceil(9.5) = 10
  EXPECT_DOUBLE_EQ(scene.frameTime(10), 1.0);
}

TEST(SceneLoader, RunsTakeTheScenesPhysicsAndStartUnlessTheyGiveTheirOwn) {
  const Scene scene = parseScene(R"({
    "name": "per-run", "linkage": { "rods": 4, "L": 3.0, "hinge_masses": [2, 2, 2] },
    "initial": { "coords": [0.3, 0.2], "velocity": [0.5, 0.7] }, "duration": 1,
    "runs": [ { "name": "shared", "method": "ambient" },
              { "name": "own L", "method": "ambient", "linkage": { "L": 2.5 } },
              { "name": "own masses and start", "method": "christoffel",
                "linkage": { "rod_masses": [1, 0, 0, 1] },
                "initial": { "drag": { "point": [1, 0, 0], "direction": [0, 1, 0] }, "unit_speed": true } } ]
  })", "per-run.json");
  ASSERT_EQ(scene.runs.size(), 3u);
  const RunSpec& shared = scene.runs[0];
  EXPECT_FALSE(shared.ownLinkage);
  EXPECT_FALSE(shared.ownInitial);
  EXPECT_DOUBLE_EQ(shared.chain.baseLength, 3.0);
  EXPECT_EQ(shared.chain.hingeMasses, scene.chain.hingeMasses);
  EXPECT_EQ(shared.initial.coords, scene.initial.coords);
  // A run's linkage changes what it gives and keeps the scene's values for the rest.
  const RunSpec& ownL = scene.runs[1];
  EXPECT_TRUE(ownL.ownLinkage);
  EXPECT_DOUBLE_EQ(ownL.chain.baseLength, 2.5);
  EXPECT_EQ(ownL.chain.rods, 4);
  EXPECT_EQ(ownL.chain.hingeMasses, Eigen::VectorXd::Constant(3, 2.0));
  const RunSpec& own = scene.runs[2];
  EXPECT_DOUBLE_EQ(own.chain.baseLength, 3.0);
  EXPECT_DOUBLE_EQ(own.chain.rodMasses(3), 1.0);
  EXPECT_EQ(own.chain.hingeMasses, Eigen::VectorXd::Constant(3, 2.0));
  // A run's start replaces the scene's whole (here a drag instead of chart coordinates).
  EXPECT_TRUE(own.ownInitial);
  EXPECT_EQ(own.initial.kind, InitialSpec::Kind::Drag);
  EXPECT_TRUE(own.initial.unitSpeed);
  EXPECT_EQ(scene.initial.kind, InitialSpec::Kind::ChartCoordinates);
  EXPECT_FALSE(scene.initial.unitSpeed);
}

TEST(SceneLoader, ShippedScenesLoad) {
  for (const char* name :
       {"default.json", "comparison.json", "pole-passage.json", "seam.json", "massive-rods.json", "five-rods.json"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(loadScene(shippedScene(name)));
  }
}

TEST(SceneLoader, ShippedDefaultIsTheSpecsDemo) {
  const Scene scene = loadScene(shippedScene("default.json"));
  EXPECT_EQ(scene.chain.rods, 4);
  EXPECT_DOUBLE_EQ(scene.chain.baseLength, 3.0);
  EXPECT_EQ(scene.initial.kind, InitialSpec::Kind::Drag);
  EXPECT_TRUE(scene.initial.unitSpeed);
  EXPECT_EQ(scene.frameCount(), 601);
  EXPECT_EQ(scene.output.size.width, 1280);
}

TEST(SceneLoader, MissingFileIsAProblemNotACrash) {
  try {
    loadScene("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.json: cannot open"), std::string::npos);
  }
}

// A scene file past kMaxSceneBytes is refused by its size, after one bounded read (a 100 MB file took
// 2 GB of memory); one of exactly that size is read and judged as JSON.
TEST(SceneLoader, FilesBeyondTheSizeLimitAreRefusedWithoutBeingReadWhole) {
  testing::TempFolder folder;
  const std::string big = folder / "big.json";
  {
    std::ofstream out(big, std::ios::binary);
    out << std::string(limits::kMaxSceneBytes + 1, ' ');
  }
  try {
    loadScene(big);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("larger than 16 MiB"), std::string::npos) << error.what();
  }
  std::filesystem::resize_file(big, limits::kMaxSceneBytes);
  try {
    loadScene(big);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("malformed JSON"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace sl
