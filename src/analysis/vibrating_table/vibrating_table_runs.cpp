#include "analysis/vibrating_table/vibrating_table_runs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "analysis/vibrating_table/vibrating_table_theory.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"

namespace impact::vibrating_table {

namespace {

// Collects the events of a run after the transient.
struct EventCollector {
  const TableScene* scene;
  double transient_end;
  std::size_t max_events;
  TableRun* run;

  void operator()(double t, EventKind kind, double v_after) const {
    if (kind == EventKind::impact) ++run->impacts;
    if (t < transient_end || run->events.size() >= max_events) return;
    run->events.push_back(
        {t, kind, wrap_phase(scene->omega * t + scene->phase), v_after / scene->speed_unit()});
  }
};

}  // namespace

Model table_model(const TableScene& scene) {
  Model model;
  model.phi = 0.0;
  model.f = -scene.g;
  model.cor = scene.e;
  model.harmonic = Harmonic{scene.gamma * scene.g, scene.omega, scene.phase};
  return model;
}

TableScene table_scene_on_orbit(double gamma, double e, int n) {
  const std::optional<PeriodOneOrbit> orbit = period_one_orbit(gamma, e, n);
  if (!orbit)
    throw std::invalid_argument(
        "no period-1 orbit at Gamma = " + std::to_string(gamma) +
        " below Gamma_1 = " + std::to_string(period_one_existence_threshold(e, n)));
  TableScene scene;
  scene.gamma = gamma;
  scene.e = e;
  scene.phase = orbit->impact.phase;
  scene.initial = {0.0, orbit->impact.speed * scene.speed_unit()};
  return scene;
}

TableRun run_table(const TableScene& scene, const MethodParams& method, double h, int periods,
                   int transient, std::size_t max_events) {
  TableRun run;
  const EventCollector collect{&scene, transient * scene.period(), max_events, &run};
  const Scene table =
      make_scene(table_model(scene), scene.initial, periods * scene.period(), h, method);
  AnyStepper any = make_stepper(table);
  // The events of `impact run --events`: a time-stepper's read off its steps by its rules.
  RunOutputs outputs;
  outputs.events = [&](const Event& event) { collect(event.t, event.kind, event.v_after); };
  outputs.watch = [&](std::int64_t, const State& s, const StepInfo&) { run.final_state = s; };
  try {
    run_scene(table, any, outputs);
  } catch (const std::exception& e) {
    throw std::runtime_error(
        std::string(method_name(method)) + " at h = " + round_trip(h) +
        ", e = " + round_trip(scene.e) + ", Gamma = " + round_trip(scene.gamma) +
        " from u = " + round_trip(scene.initial.u) + ", v = " + round_trip(scene.initial.v) +
        ", table phase " + round_trip(scene.phase) + ": " + e.what());
  }
  run.steps = table.grid.steps;
  return run;
}

std::vector<TableSample> sample_table(const TableScene& scene, const MethodParams& method, double h,
                                      int periods) {
  const Grid grid = Grid::covering(periods * scene.period(), h);
  std::vector<TableSample> samples;
  samples.reserve(static_cast<std::size_t>(grid.steps) + 1);
  AnyStepper stepper = make_stepper(table_model(scene), h, method);
  simulate(stepper, scene.initial, grid, [&](std::int64_t l, const State& s, const StepInfo&) {
    samples.push_back({grid.t(l), s});
  });
  return samples;
}

TableClassification classify_table_run(const TableRun& run, const TableScene& scene,
                                       double tolerance) {
  TableClassification c;
  if (run.events.empty()) {
    c.regime = TableRegime::resting;
    return c;
  }
  std::vector<const TableEvent*> impacts;
  for (const TableEvent& event : run.events) {
    if (event.kind != EventKind::impact) c.regime = TableRegime::sticking;
    if (event.kind == EventKind::impact) impacts.push_back(&event);
  }
  std::vector<double> steps;
  for (std::size_t k = 1; k < impacts.size(); ++k)
    steps.push_back(std::fabs(impacts[k]->speed - impacts[k - 1]->speed));
  if (!steps.empty()) {
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    c.split = steps[steps.size() / 2];
  }
  if (c.regime == TableRegime::sticking || impacts.size() < 4) return c;
  // A repetition after p impacts: speeds and phases (on the circle) agree p impacts apart.
  const auto repeats = [&](std::size_t p) {
    double worst = 0.0;
    for (std::size_t k = p; k < impacts.size(); ++k) {
      const double dphase =
          std::remainder(impacts[k]->phase - impacts[k - p]->phase, 2 * std::numbers::pi);
      worst = std::max(
          {worst, std::fabs(dphase), std::fabs(impacts[k]->speed - impacts[k - p]->speed)});
    }
    return worst;
  };
  for (std::size_t p = 1; p <= 16 && 2 * p <= impacts.size(); ++p) {
    const double spread = repeats(p);
    if (spread <= tolerance) {
      c.regime = p == 1 ? TableRegime::period_one : TableRegime::periodic;
      c.period = static_cast<int>(p);
      c.spread = spread;
      break;
    }
  }
  // Period one also needs whole table periods between impacts (a phase-locked orbit).
  if (c.regime == TableRegime::period_one) {
    const double flight = scene.omega * (impacts[1]->t - impacts[0]->t);
    const double n = std::round(flight / (2 * std::numbers::pi));
    if (n < 1 || std::fabs(flight - 2 * std::numbers::pi * n) > tolerance)
      c.regime = TableRegime::periodic;
  }
  return c;
}

std::string_view regime_name(TableRegime regime) {
  switch (regime) {
    case TableRegime::period_one:
      return "period_one";
    case TableRegime::periodic:
      return "periodic";
    case TableRegime::aperiodic:
      return "aperiodic";
    case TableRegime::sticking:
      return "sticking";
    case TableRegime::resting:
      return "resting";
    case TableRegime::failed:
      return "failed";
  }
  return "aperiodic";
}

}  // namespace impact::vibrating_table
