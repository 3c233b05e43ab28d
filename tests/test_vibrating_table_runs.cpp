// The pieces of the vibrating-table experiment: a time-stepper's events from N^l, the
// classification of a run, the grid of Gamma and the two readings of the period doubling.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "analysis/vibrating_table/vibrating_table_sweep.hpp"
#include "analysis/vibrating_table/vibrating_table_theory.hpp"

using namespace impact;
using namespace impact::vibrating_table;

namespace {

SweepPoint synthetic(double gamma, double split) {
  SweepPoint p;
  p.gamma = gamma;
  p.classification.regime = split > 0 ? TableRegime::periodic : TableRegime::period_one;
  p.classification.period = split > 0 ? 2 : 1;
  p.classification.split = split;
  return p;
}

}  // namespace

TEST_CASE("vibrating table: direct's impacts on the period-1 orbit, one per period at its phase",
          "[vibrating_table]") {
  const double gamma = 1.2, e = 0.5, h = 1e-4;
  const TableScene scene = table_scene_on_orbit(gamma, e);
  const PeriodOneOrbit orbit = *period_one_orbit(gamma, e, 1);
  const TableRun run = run_table(scene, find_method("direct")->defaults, h, 200, 180);
  // One impact per table period (0.1 s) after the transient, none resting; each dated where the
  // step's free flight under its mean force crosses the floor (StepEvents), which is direct's own
  // closed-form flight, so its phase is off the orbit's only by the scheme's O(h) drift of the
  // orbit (measured 0.21 omega h; bounded here by one step, omega h = 6.3e-3 rad), and its
  // take-off speed e |v^l| within e g h of it (the impulse acts at the step's end, (4-4)).
  REQUIRE(run.events.size() == 20);
  const double step_phase = scene.omega * h;
  for (const TableEvent& event : run.events) {
    CHECK(event.kind == EventKind::impact);
    CHECK(std::fabs(std::remainder(event.phase - orbit.impact.phase, 2 * std::numbers::pi)) <
          step_phase);
    CHECK(std::fabs(event.speed - orbit.impact.speed) < 3 * step_phase);
  }
  CHECK(classify_table_run(run, scene, 1.5 * step_phase).regime == TableRegime::period_one);
}

TEST_CASE("vibrating table: below Gamma = 1 a ball on the table rests, in exact and in direct",
          "[vibrating_table]") {
  TableScene scene;
  scene.gamma = 0.5;
  scene.e = 0.5;
  scene.initial = {0.002, 0.0};  // dropped from 2 mm: a chatter, then rest for good
  for (const char* method : {"exact", "direct", "moreau_jean"}) {
    INFO(method);
    const TableRun run = run_table(scene, find_method(method)->defaults, 1e-4, 30, 10);
    CHECK(run.impacts > 0);
    CHECK(run.events.empty());
    CHECK(classify_table_run(run, scene, 1e-6).regime == TableRegime::resting);
  }
}

TEST_CASE("vibrating table: the grid of Gamma and the readings of the period doubling",
          "[vibrating_table]") {
  const std::vector<double> up = gamma_grid(0.2, 2.6, 0.01), down = gamma_grid(2.6, 0.2, -0.01);
  CHECK(up.size() == 241);
  CHECK(up.back() == Approx(2.6).epsilon(1e-12));
  CHECK(down.size() == 241);
  CHECK(down.back() == Approx(0.2).epsilon(1e-12));
  // split^2 = 0.5 (Gamma - 1.3) above 1.3: the fit returns 1.3 and the crossing of 0.1 is where
  // split^2 = 0.01, Gamma = 1.32, both to rounding (the data are exactly linear in split^2).
  std::vector<SweepPoint> sweep;
  for (double gamma : gamma_grid(1.2, 1.5, 0.005))
    sweep.push_back(synthetic(gamma, gamma > 1.3 ? std::sqrt(0.5 * (gamma - 1.3)) : 0.0));
  int used = 0;
  CHECK(fit_period_doubling(sweep, 0.03, 0.12, &used) == Approx(1.3).margin(1e-8));
  CHECK(used >= 4);
  CHECK(split_crossing(sweep, 0.1) == Approx(1.32).margin(1e-8));
  // A failed point is skipped by both, and ends no period-1 block.
  sweep[30].classification.regime = TableRegime::failed;
  CHECK(split_crossing(sweep, 0.1) == Approx(1.32).margin(1e-8));
  std::reverse(sweep.begin(), sweep.end());
  std::size_t keeps = 0, leaves = 0;
  CHECK(std::isnan(lowest_period_one(sweep, &keeps, &leaves)));  // never leaves going down
}

TEST_CASE("vibrating table: exact's period-2 orbit at Gamma = 1.6 is the numeric impact map's",
          "[vibrating_table]") {
  // Past Gamma_pd = 1.527 (e = 0.5) both settle on the period-2 orbit from the same start (the
  // period-1 orbit with its take-off speed raised by 1e-3): the map of vibrating_table_theory
  // (ForceFunction's flight, its own root bracketing) and exact (its event track), two
  // independent codes. After 600 impacts both have forgotten the start (the period-2 orbit is
  // stable here, 0.07 above Gamma_pd), so their take-off speeds differ only by the rounding of
  // the impact times, amplified by the flights: far below 1e-8 (measured: within 1e-12).
  const double gamma = 1.6, e = 0.5;
  TableScene scene = table_scene_on_orbit(gamma, e);
  scene.initial.v *= 1 + 1e-3;
  TableImpact impact{scene.phase, scene.initial.v / scene.speed_unit()};
  std::vector<double> map_speeds;
  for (int k = 0; k < 600; ++k) {
    const std::optional<MapStep> step = impact_map(impact, gamma, e);
    REQUIRE(step);
    impact = step->next;
    map_speeds.push_back(impact.speed);
  }
  const TableRun run = run_table(scene, find_method("exact")->defaults, 0.1 / 16, 600, 596);
  REQUIRE(run.events.size() >= 2);
  const double a = run.events[run.events.size() - 2].speed, b = run.events.back().speed;
  const double p = map_speeds[map_speeds.size() - 2], q = map_speeds.back();
  CHECK(std::fabs(a - b) > 0.1);  // a genuine period 2: the split is ~0.19 g / omega here
  CHECK(std::min(a, b) == Approx(std::min(p, q)).margin(1e-8));
  CHECK(std::max(a, b) == Approx(std::max(p, q)).margin(1e-8));
}
