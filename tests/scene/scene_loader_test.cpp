// Loading good scenes: every key lands where the rest of the program reads it.
#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace sl {
namespace {

using testing::shippedScene;
using testing::testLimits;

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
  const Scene scene = parseScene(kFullScene, "full.json", testLimits());
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
  EXPECT_EQ(scene.runs[0].config.method, "embedded");
  EXPECT_DOUBLE_EQ(scene.runs[0].config.tolerance, 1e-9);
  EXPECT_DOUBLE_EQ(scene.runs[0].config.maxRelativeEnergyDrift, 0.1);
  EXPECT_DOUBLE_EQ(scene.runs[0].config.maxRodLengthError, 1e-4);
  EXPECT_EQ(scene.runs[0].config.maxSteps, 1000);
  EXPECT_FLOAT_EQ(scene.runs[0].color->b, 0.5f);
  EXPECT_DOUBLE_EQ(scene.runs[1].config.step, 0.05);
  EXPECT_EQ(scene.output.fps, 24);
  EXPECT_EQ(scene.output.folder, "somewhere");
  EXPECT_FALSE(scene.output.png);
  EXPECT_EQ(scene.output.video, "v.mp4");
  const RenderSettings& render = scene.view.render;
  EXPECT_EQ(render.width, 640);
  EXPECT_EQ(render.height, 360);
  ASSERT_EQ(render.panels.size(), 3u);
  EXPECT_EQ(render.panels[1].kind, PanelKind::Plot);
  EXPECT_EQ(render.panels[2].plotIndex, 1);
  ASSERT_TRUE(render.panels[1].rect.has_value());
  EXPECT_DOUBLE_EQ((*render.panels[1].rect)[1], 0.5);
  ASSERT_EQ(scene.view.plots.size(), 2u);
  EXPECT_EQ(scene.view.plots[0].kind, PlotKind::EnergyError);
  EXPECT_FALSE(scene.view.plots[0].logY);
  EXPECT_EQ(scene.view.plots[1].kind, PlotKind::Divergence);  // two runs: divergence by default
  EXPECT_DOUBLE_EQ(render.camera.viewDirection.z, 1);
  EXPECT_DOUBLE_EQ(render.camera.orbitDegreesPerSecond, 5);
  EXPECT_DOUBLE_EQ(render.camera.fieldOfViewDegrees, 40);
  EXPECT_EQ(render.linkageLayout, LinkageLayout::SideBySide);
  EXPECT_EQ(render.linkageRun, 1);
  EXPECT_EQ(scene.view.trailHinges, (std::vector<int>{1, 4}));
  EXPECT_DOUBLE_EQ(render.trailFadeSeconds, 3);
  EXPECT_DOUBLE_EQ(render.pathFadeSeconds, 4);
  EXPECT_EQ(scene.view.pathSamplesPerFrame, 2);
  EXPECT_FLOAT_EQ(render.background.r, 0);
  EXPECT_FALSE(render.antialias);
}

TEST(SceneLoader, DefaultsFillWhatIsLeftOut) {
  const Scene scene = parseScene(R"({"name": "d", "linkage": {"rods": 4, "L": 3},
      "initial": {"coords": [0, 0], "velocity": [1, 0]}, "duration": 1, "runs": [{"name": "r"}]})",
                                 "d.json", testLimits());
  EXPECT_EQ(scene.chain.hingeMasses, Eigen::VectorXd::Ones(3));
  EXPECT_EQ(scene.chain.rodMasses, Eigen::VectorXd::Zero(4));
  EXPECT_EQ(scene.runs[0].config.method, RunConfig{}.method);
  EXPECT_EQ(scene.output.folder, "renders/d");
  EXPECT_EQ(scene.output.fps, 30);
  EXPECT_EQ(scene.view.render.width, 1280);
  ASSERT_EQ(scene.view.render.panels.size(), 2u);
  EXPECT_EQ(scene.view.render.panels[0].kind, PanelKind::Sphere);
  EXPECT_EQ(scene.view.render.panels[1].kind, PanelKind::Linkage);
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

TEST(SceneLoader, ShippedScenesLoad) {
  for (const char* name :
       {"default.json", "comparison.json", "pole-passage.json", "seam.json", "massive-rods.json", "five-rods.json"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(loadScene(shippedScene(name), testLimits()));
  }
}

TEST(SceneLoader, ShippedDefaultIsTheSpecsDemo) {
  const Scene scene = loadScene(shippedScene("default.json"), testLimits());
  EXPECT_EQ(scene.chain.rods, 4);
  EXPECT_DOUBLE_EQ(scene.chain.baseLength, 3.0);
  EXPECT_EQ(scene.initial.kind, InitialSpec::Kind::Drag);
  EXPECT_TRUE(scene.initial.unitSpeed);
  EXPECT_EQ(scene.frameCount(), 601);
  EXPECT_EQ(scene.output.width, 1280);
}

TEST(SceneLoader, MissingFileIsAProblemNotACrash) {
  try {
    loadScene("/nonexistent/scene.json", testLimits());
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.json: cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace sl
