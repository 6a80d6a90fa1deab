// The cheapest-setting logic and the CSV of a work-precision sweep, on synthetic rows.

#include <gtest/gtest.h>

#include "analysis/work_precision.hpp"
#include "contracts/registry.hpp"

namespace sl {
namespace {

WorkPrecisionPoint point(const std::string& start, Integrator integrator, double setting, double error,
                         long evaluations, const RunStatus& status = Verdict::Ok) {
  WorkPrecisionPoint p{start, Method::Embedded, integrator, setting, Method::Ambient, {}};
  p.measurement.status = status;
  p.measurement.maxError = error;
  p.measurement.finalError = error / 2;
  p.measurement.evaluations = evaluations;
  p.measurement.wallSeconds = evaluations * 1e-6;
  return p;
}

TEST(CheapestSettings, PicksTheFewestEvaluationsReachingTheTargetOnEveryStart) {
  const std::vector<WorkPrecisionPoint> points = {
      point("a", Integrator::Dopri5, 1e-6, 1e-7, 100),   point("b", Integrator::Dopri5, 1e-6, 3e-6, 120),
      point("a", Integrator::Dopri5, 1e-9, 1e-10, 300),  point("b", Integrator::Dopri5, 1e-9, 5e-10, 350),
      point("a", Integrator::Dopri5, 1e-12, 1e-13, 900), point("b", Integrator::Dopri5, 1e-12, 2e-13, 800)};
  const auto cheapest = cheapestSettings(points, {1e-6, 1e-9, 1e-12, 1e-14});
  ASSERT_EQ(cheapest.size(), 4u);
  // 1e-6: tol 1e-6 fails on start b (3e-6), so tol 1e-9 is the cheapest that holds everywhere.
  EXPECT_TRUE(cheapest[0].reached);
  EXPECT_EQ(cheapest[0].setting, 1e-9);
  EXPECT_EQ(cheapest[0].worstEvaluations, 350);
  EXPECT_DOUBLE_EQ(cheapest[0].worstError, 5e-10);
  EXPECT_EQ(cheapest[1].setting, 1e-9);
  EXPECT_EQ(cheapest[2].setting, 1e-12);
  EXPECT_EQ(cheapest[2].worstEvaluations, 900);
  EXPECT_FALSE(cheapest[3].reached);
  const std::string text = cheapestSettingsText(cheapest, {1e-6, 1e-9, 1e-12, 1e-14});
  EXPECT_NE(text.find("never"), std::string::npos);
  // The table shows the cost the choice was made by (evaluations), so a tighter target never looks
  // cheaper than a looser one; the noisy wall time comes second.
  EXPECT_NE(text.find("900 evals"), std::string::npos) << text;
  for (std::size_t i = 1; i < 3; ++i) EXPECT_GE(cheapest[i].worstEvaluations, cheapest[i - 1].worstEvaluations);
}

// The console table's columns line up on every row, whatever the lengths of the names and cells (the
// bulirsch-stoer rows and long cells once pushed theirs right).
TEST(CheapestSettings, TheTableColumnsLineUpOnEveryRow) {
  std::vector<WorkPrecisionPoint> points;
  for (const Integrator integrator : {Integrator::Rk4, Integrator::BulirschStoer})
    for (double setting : {1e-3, 1e-9}) points.push_back(point("a", integrator, setting, setting / 10, 123456));
  const std::vector<double> targets = {1e-6, 1e-9};
  const std::string text = cheapestSettingsText(cheapestSettings(points, targets), targets);
  std::vector<std::vector<size_t>> bars;
  for (size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = text.substr(start, end - start);
    bars.emplace_back();
    for (size_t at = line.find('|'); at != std::string::npos; at = line.find('|', at + 1)) bars.back().push_back(at);
  }
  ASSERT_EQ(bars.size(), 3u) << text;  // header and two integrators
  for (const auto& row : bars) EXPECT_EQ(row, bars.front()) << text;
  EXPECT_EQ(bars.front().size(), targets.size());
}

TEST(CheapestSettings, AFailedOrMissingStartDisqualifiesASetting) {
  const std::vector<WorkPrecisionPoint> points = {
      point("a", Integrator::Rk4, 0.01, 1e-11, 8000),
      point("b", Integrator::Rk4, 0.01, 1e-12, 8000, StopReason::PoleFoldBack),
      point("a", Integrator::Rk4, 0.001, 1e-12, 80000), point("b", Integrator::Rk4, 0.001, 1e-13, 80000),
      point("a", Integrator::Rk4, 0.1, 1e-13, 800)};  // start b never ran at 0.1
  const auto cheapest = cheapestSettings(points, {1e-9});
  ASSERT_EQ(cheapest.size(), 1u);
  EXPECT_TRUE(cheapest[0].reached);
  EXPECT_EQ(cheapest[0].setting, 0.001);
}

TEST(CheapestSettings, ANonFiniteErrorNeverQualifies) {
  const std::vector<WorkPrecisionPoint> points = {point("a", Integrator::Dopri5, 1e-8, std::nan(""), 10)};
  EXPECT_FALSE(cheapestSettings(points, {1e-3})[0].reached);
}

TEST(WorkPrecisionCsv, HasNamedColumnsAndRoundTrips) {
  const std::vector<WorkPrecisionPoint> points = {
      point("generic", Integrator::Rk4, 0.01, 1.25e-7, 8004),
      point("through-pole", Integrator::Dopri5, 1e-10, 3e-11, 1234, StopReason::NonFinite)};
  const CsvTable table = workPrecisionTable(points);
  const std::vector<std::string> expected = {"start",
                                             "method",
                                             "integrator",
                                             "setting_kind",
                                             "setting",
                                             "status",
                                             "wall_seconds",
                                             "cpu_seconds",
                                             "evaluations",
                                             "steps",
                                             "final_error",
                                             "max_error",
                                             "max_energy_drift",
                                             "max_rod_length_error",
                                             "stop_time",
                                             "reference_method",
                                             "stop_detail"};
  EXPECT_EQ(table.columns, expected);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.text(0, "setting_kind"), "h");
  EXPECT_EQ(table.text(1, "setting_kind"), "tol");
  EXPECT_EQ(table.text(0, "max_error"), "1.25e-07");
  const auto back = workPrecisionPointsFromTable(table);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].measurement.status, RunStatus(StopReason::NonFinite));
  EXPECT_EQ(back[0].measurement.maxError, 1.25e-7);
  EXPECT_EQ(back[0].measurement.evaluations, 8004);
  EXPECT_EQ(back[1].setting, 1e-10);
}

TEST(WorkPrecisionCsv, WritesNamesAndReadsThemBackAsKinds) {
  const CsvTable table = workPrecisionTable({point("generic", Integrator::BulirschStoer, 1e-9, 1e-10, 500)});
  EXPECT_EQ(table.text(0, "method"), "embedded");
  EXPECT_EQ(table.text(0, "integrator"), "bulirsch-stoer");
  EXPECT_EQ(table.text(0, "reference_method"), "ambient");
  EXPECT_EQ(table.text(0, "status"), "ok");
  const auto back = workPrecisionPointsFromTable(table);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].method, Method::Embedded);
  EXPECT_EQ(back[0].integrator, Integrator::BulirschStoer);
  EXPECT_EQ(back[0].referenceMethod, Method::Ambient);
  EXPECT_FALSE(back[0].measurement.failed());

  CsvTable unknown = table;
  unknown.rows[0][unknown.column("method")] = "euler";
  EXPECT_THROW(workPrecisionPointsFromTable(unknown), std::invalid_argument);
  unknown = table;
  unknown.rows[0][unknown.column("status")] = "pole-singularity";
  EXPECT_THROW(workPrecisionPointsFromTable(unknown), std::invalid_argument);
}

}  // namespace
}  // namespace sl
