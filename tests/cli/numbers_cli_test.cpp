// `linkage numbers`: a scene's results in one JSON document, checked against the commands that compute them one
// by one (simulate's CSV and events, geometry --summary).
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

nlohmann::json numbersOf(const std::vector<std::string>& args, const TempFolder& folder) {
  const ProcessResult result = runLinkage(args, folder.path());
  EXPECT_EQ(result.code, 0) << result.err;
  return nlohmann::json::parse(result.out);
}

// Lines of simulate --events for `run`: event name -> times.
std::vector<std::pair<std::string, double>> eventsOf(const std::string& path, const std::string& run) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::pair<std::string, double>> events;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string name, member, event, time;
    std::getline(fields, name, ',');
    std::getline(fields, member, ',');
    std::getline(fields, event, ',');
    std::getline(fields, time);
    if (name == run && member == "0") events.push_back({event, std::stod(time)});
  }
  return events;
}

TEST(NumbersCli, ConjugatePointsAndStopsAreThoseSimulateWrites) {
  TempFolder folder;
  const nlohmann::json jacobi = numbersOf({"numbers", shippedScene("jacobi.json")}, folder);
  ASSERT_EQ(runLinkage({"simulate", shippedScene("jacobi.json"), "--csv", "j.csv", "--events", "j.csv.events",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  const nlohmann::json& run = jacobi.at("runs").at(0);
  std::vector<double> conjugate;
  for (const auto& [event, time] : eventsOf((folder.path() / "j.csv.events").string(), run.at("name")))
    if (event == "conjugate-point") conjugate.push_back(time);
  ASSERT_FALSE(conjugate.empty());
  EXPECT_EQ(run.at("conjugate_points").get<std::vector<double>>(), conjugate);
  EXPECT_EQ(run.at("outcome"), "ran");
  EXPECT_LT(run.at("max_relative_energy_drift").get<double>(), 1e-10);
  EXPECT_GT(run.at("energy").get<double>(), 0);

  const nlohmann::json seam = numbersOf({"numbers", shippedScene("seam.json")}, folder);
  ASSERT_EQ(runLinkage({"simulate", shippedScene("seam.json"), "--csv", "s.csv", "--events", "s.events", "--quiet"},
                       folder.path())
                .code,
            0);
  const nlohmann::json& published = seam.at("runs").at(1);
  ASSERT_EQ(published.at("outcome"), "stopped");
  const auto stops = eventsOf((folder.path() / "s.events").string(), published.at("name"));
  ASSERT_EQ(stops.size(), 1u);
  EXPECT_EQ(published.at("stop").at("reason"), stops[0].first);
  EXPECT_EQ(published.at("stop").at("time").get<double>(), stops[0].second);
  EXPECT_EQ(published.at("end_time").get<double>(), stops[0].second);
  EXPECT_FALSE(seam.at("runs").at(0).contains("conjugate_points"));  // no Jacobi fields asked for
}

// The energy is the CSV's first energy value; the curvature summary is geometry --summary's, to the last bit.
TEST(NumbersCli, EnergyAndCurvatureAreThoseOfTheOtherCommands) {
  TempFolder folder;
  const nlohmann::json numbers = numbersOf({"numbers", shippedScene("default.json"), "--set", "linkage.L=3.2"}, folder);
  const nlohmann::json geometry =
      numbersOf({"geometry", shippedScene("default.json"), "--set", "linkage.L=3.2", "--summary"}, folder);
  EXPECT_EQ(numbers.at("geometry"), geometry);
  EXPECT_NEAR(numbers.at("geometry").at("total_curvature").get<double>(), 4 * M_PI, 1e-9);
  EXPECT_EQ(numbers.at("L").get<double>(), 3.2);
  ASSERT_EQ(runLinkage({"simulate", shippedScene("default.json"), "--set", "linkage.L=3.2", "--csv", "d.csv",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  std::ifstream csv(folder.path() / "d.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  std::vector<std::string> names, values;
  for (std::stringstream h(header), v(first); ;) {
    std::string a, b;
    if (!std::getline(h, a, ',') || !std::getline(v, b, ',')) break;
    names.push_back(a);
    values.push_back(b);
  }
  const auto energy = std::find(names.begin(), names.end(), "energy") - names.begin();
  ASSERT_LT(size_t(energy), names.size());
  EXPECT_EQ(numbers.at("runs").at(0).at("energy").get<double>(), std::stod(values[size_t(energy)]));
  EXPECT_EQ(numbers.at("runs").at(0).at("end_time").get<double>(), 20);
  // Five rods: no surface, no geometry.
  EXPECT_FALSE(numbersOf({"numbers", shippedScene("five-rods.json")}, folder).contains("geometry"));
}

}  // namespace
}  // namespace sl::testing
