#include "analysis/vibrating_table/vibrating_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/vibrating_table/vibrating_table_theory.hpp"
#include "impact/output/csv.hpp"

namespace impact::vibrating_table {

namespace {

const MethodParams& method_named(std::string_view name) {
  return find_method(name)->defaults;
}

// An exact solution (the reference), not a time-stepper.
bool is_reference(std::string_view method) {
  return find_method(method)->can.reference;
}

// What "repeats" means for a method's impacts (classify_table_run): to 1e-6 for exact; for a
// time-stepper to 1.5 omega h: its contact lands on the grid, so an orbit of the continuous system
// can alternate between two neighbouring contact steps; the impact's date (StepEvents's crossing of
// the floor inside the step) follows the flight, but the take-off speed e |v^l| jumps with the
// step that applies the impulse (4-4), by about e g h, i.e. e omega h in units of g / omega, and
// the scheme's flight from a take-off a step later moves the next crossing by up to omega h.
double repeat_tolerance(std::string_view method, double h) {
  return is_reference(method) ? 1e-6 : 1.5 * kTableOmega * h;
}

// One continuation sweep of a diagram: the method, its step, e, and the direction.
struct DiagramSweep {
  std::string_view method;
  double h = 0.0;
  double e = 0.0;
  bool up = true;
  std::vector<SweepPoint> points;
};

// Both sweeps of one method and e over [kTableGammaMin, kTableGammaMax], each started with the
// ball at rest on the table at its first Gamma.
void add_diagram(std::vector<DiagramSweep>& out, std::string_view method, double h, double e,
                 double step) {
  for (bool up : {true, false}) {
    TableScene start;
    start.e = e;
    const std::vector<double> gammas = up ? gamma_grid(kTableGammaMin, kTableGammaMax, step)
                                          : gamma_grid(kTableGammaMax, kTableGammaMin, -step);
    SweepSettings settings;
    settings.periods = kTableDiagramPeriods;
    settings.max_events = kTableDiagramEvents;
    settings.transient = kTableDiagramTransient;
    settings.tolerance = repeat_tolerance(method, h);
    out.push_back(
        {method, h, e, up, sweep_table(start, method_named(method), h, gammas, settings)});
  }
}

// The events of the exact sweeps (exact = true) or of the time-steppers' (false): two files, so
// that each figure reads only its own.
std::string diagram_csv(const std::vector<DiagramSweep>& sweeps, bool exact) {
  std::ostringstream csv;
  csv << "method,h,e,sweep,gamma,kind,phase,speed\n";
  for (const DiagramSweep& s : sweeps)
    if (is_reference(s.method) == exact)
      for (const SweepPoint& p : s.points)
        for (const TableEvent& event : p.events)
          csv << s.method << ',' << round_trip(s.h) << ',' << s.e << ',' << (s.up ? "up" : "down")
              << ',' << round_trip(p.gamma) << ',' << event_name(event.kind) << ','
              << round_trip(event.phase) << ',' << round_trip(event.speed) << '\n';
  return csv.str();
}

void regime_rows(std::ostringstream& csv, std::string_view method, double h, double e,
                 std::string_view sweep, const std::vector<SweepPoint>& points) {
  for (const SweepPoint& p : points)
    csv << method << ',' << round_trip(h) << ',' << e << ',' << sweep << ',' << round_trip(p.gamma)
        << ',' << regime_name(p.classification.regime) << ',' << p.classification.period << ','
        << round_trip(p.classification.split) << '\n';
}

std::string regimes_csv(const std::vector<DiagramSweep>& sweeps,
                        const std::vector<TableThresholds>& thresholds) {
  std::ostringstream csv;
  csv << "method,h,e,sweep,gamma,regime,period,split\n";
  for (const DiagramSweep& s : sweeps)
    regime_rows(csv, s.method, s.h, s.e, s.up ? "up" : "down", s.points);
  for (const TableThresholds& t : thresholds) {
    regime_rows(csv, "exact", kTableExactStep, t.e, "existence_window", t.exact.existence_window);
    regime_rows(csv, "exact", kTableExactStep, t.e, "period_doubling_window",
                t.exact.period_doubling_window);
  }
  return csv.str();
}

void threshold_row(std::ostringstream& csv, std::string_view method, double h, double e,
                   const ThresholdMeasurement& m, const ThresholdMeasurement& exact) {
  csv << method << ',' << round_trip(h) << ',' << e << ',' << round_trip(m.existence) << ','
      << round_trip(m.period_doubling) << ',' << m.fit_points << ','
      << round_trip(m.branch_crossing) << ','
      << round_trip(m.branch_crossing - exact.branch_crossing) << '\n';
}

std::string thresholds_csv(const std::vector<TableThresholds>& thresholds) {
  std::ostringstream csv;
  csv << "method,h,e,existence,period_doubling,fit_points,branch_crossing,"
         "branch_crossing_minus_exact\n";
  for (const TableThresholds& t : thresholds) {
    csv << "closed_form,0," << t.e << ',' << round_trip(period_one_existence_threshold(t.e, 1))
        << ',' << round_trip(period_doubling_threshold(t.e, 1)) << ",0,nan,nan\n";
    threshold_row(csv, "exact", kTableExactStep, t.e, t.exact, t.exact);
    for (std::size_t m = 0; m < kTableSteppers.size(); ++m)
      for (std::size_t k = 0; k < kTableThresholdSteps.size(); ++k)
        threshold_row(csv, kTableSteppers[m], kTableThresholdSteps[k], t.e, t.steppers[m][k],
                      t.exact);
  }
  return csv.str();
}

// One trajectory per regime, from the exact downward sweep's state at that Gamma (on its
// attractor), sampled every 1/400 period over four periods.
// Each label is checked against the sweep's own classification at that Gamma (period: impacts
// per repetition, 0 where any).
struct Regime {
  std::string_view name;
  double e, gamma;
  TableRegime regime;
  int period;
};
constexpr std::array<Regime, 4> kTrajectoryRegimes{
    {{"period_one", 0.5, 1.3, TableRegime::period_one, 1},
     {"period_two", 0.5, 1.6, TableRegime::periodic, 2},
     {"chaos", 0.5, 1.75, TableRegime::aperiodic, 0},
     {"sticking", 0.5, 1.03, TableRegime::sticking, 0}}};

std::string trajectories_csv(const std::vector<DiagramSweep>& sweeps) {
  std::ostringstream csv;
  csv << "regime,e,gamma,t,u,v\n";
  for (const Regime& r : kTrajectoryRegimes)
    for (const DiagramSweep& s : sweeps) {
      if (!is_reference(s.method) || s.up || s.e != r.e) continue;
      for (const SweepPoint& p : s.points) {
        if (std::fabs(p.gamma - r.gamma) > 1e-9) continue;
        if (p.classification.regime != r.regime ||
            (r.period != 0 && p.classification.period != r.period))
          throw std::logic_error("vibrating_table: the trajectory labelled " + std::string(r.name) +
                                 " at Gamma = " + std::to_string(r.gamma) + " is classified " +
                                 std::string(regime_name(p.classification.regime)) + " (period " +
                                 std::to_string(p.classification.period) + ") by the sweep");
        for (const TableSample& x :
             sample_table(p.end, method_named("exact"), p.end.period() / 400, 4))
          csv << r.name << ',' << r.e << ',' << round_trip(r.gamma) << ',' << round_trip(x.t) << ','
              << round_trip(x.state.u) << ',' << round_trip(x.state.v) << '\n';
      }
    }
  return csv.str();
}

// One time-stepper's thresholds over kTableThresholdSteps, as shifts from exact's (the branch
// crossing, measured the same way) and from the closed form (the end of the period-1 branch).
toml::table measurement_table(
    const std::array<ThresholdMeasurement, kTableThresholdSteps.size()>& m,
    const ThresholdMeasurement& exact, double g1) {
  std::vector<double> h, existence, existence_shift, crossing, crossing_shift, abs_shift, pd;
  toml::array fit_points;
  for (std::size_t k = 0; k < m.size(); ++k) {
    h.push_back(kTableThresholdSteps[k]);
    existence.push_back(m[k].existence);
    existence_shift.push_back(m[k].existence - g1);
    crossing.push_back(m[k].branch_crossing);
    crossing_shift.push_back(m[k].branch_crossing - exact.branch_crossing);
    abs_shift.push_back(std::fabs(crossing_shift.back()));
    pd.push_back(m[k].period_doubling);
    fit_points.push_back(m[k].fit_points);
  }
  const OrderFit order = fit_order(h, abs_shift);
  return toml::table{{"h", toml_array(h)},
                     {"existence", toml_array(existence)},
                     {"existence_shift", toml_array(existence_shift)},
                     {"branch_crossing", toml_array(crossing)},
                     {"branch_crossing_shift", toml_array(crossing_shift)},
                     {"branch_crossing_shift_order", order.order},
                     {"branch_crossing_shift_coarsest", crossing_shift.front()},
                     {"branch_crossing_shift_finest", crossing_shift.back()},
                     {"period_doubling_fit_upward", toml_array(pd)},
                     {"period_doubling_fit_points", fit_points}};
}

std::size_t failures(const std::vector<DiagramSweep>& sweeps, std::string_view method) {
  std::size_t n = 0;
  for (const DiagramSweep& s : sweeps)
    if (s.method == method) n += failed_points(s.points);
  return n;
}

// The first failure of a diagram, for the summary ("" when none).
std::string first_failure(const std::vector<DiagramSweep>& sweeps) {
  for (const DiagramSweep& s : sweeps)
    for (const SweepPoint& p : s.points)
      if (!p.failure.empty()) return p.failure;
  return "";
}

}  // namespace

ThresholdSettings table_threshold_settings(std::string_view method, double h) {
  ThresholdSettings settings;
  if (is_reference(method)) {
    settings.sweep.tolerance = 1e-4;
    return settings;
  }
  settings.bisections = 8;
  settings.fit_from_above = false;  // a time-stepper's fit is too noisy to refine (README)
  settings.sweep.tolerance = repeat_tolerance(method, h);
  settings.bisection_tolerance = std::max(1e-3, settings.sweep.tolerance);
  return settings;
}

TableThresholds measure_table_thresholds(double e) {
  TableThresholds t;
  t.e = e;
  t.exact = measure_thresholds(method_named("exact"), kTableExactStep, e,
                               table_threshold_settings("exact", kTableExactStep));
  for (std::size_t m = 0; m < kTableSteppers.size(); ++m)
    for (std::size_t k = 0; k < kTableThresholdSteps.size(); ++k) {
      const double h = kTableThresholdSteps[k];
      t.steppers[m][k] = measure_thresholds(method_named(kTableSteppers[m]), h, e,
                                            table_threshold_settings(kTableSteppers[m], h));
    }
  return t;
}

toml::table table_thresholds_summary(const TableThresholds& t) {
  const double g1 = period_one_existence_threshold(t.e, 1), gpd = period_doubling_threshold(t.e, 1);
  toml::table out{{"e", t.e},
                  {"existence_closed_form", g1},
                  {"period_doubling_closed_form", gpd},
                  {"existence_exact", t.exact.existence},
                  {"existence_exact_shift", t.exact.existence - g1},
                  {"period_doubling_exact", t.exact.period_doubling},
                  {"period_doubling_exact_shift", t.exact.period_doubling - gpd},
                  {"period_doubling_exact_fit_points", t.exact.fit_points},
                  {"branch_crossing_exact", t.exact.branch_crossing},
                  {"existence_exact_bisection_failure", t.exact.bisection_failure}};
  for (std::size_t m = 0; m < kTableSteppers.size(); ++m)
    out.insert(kTableSteppers[m], measurement_table(t.steppers[m], t.exact, g1));
  return out;
}

toml::table run_vibrating_table(const ExperimentContext& context) {
  std::vector<DiagramSweep> sweeps;
  for (double e : kTableRestitutions)
    add_diagram(sweeps, "exact", kTableExactStep, e, kTableExactGammaStep);
  for (std::string_view method : kTableSteppers)
    for (double h : kTableDiagramSteps)
      for (double e : kTableRestitutions) add_diagram(sweeps, method, h, e, kTableStepperGammaStep);
  std::vector<TableThresholds> thresholds;
  for (double e : kTableRestitutions) thresholds.push_back(measure_table_thresholds(e));

  context.write("diagram_exact.csv", [&] { return diagram_csv(sweeps, true); });
  context.write("diagram_steppers.csv", [&] { return diagram_csv(sweeps, false); });
  context.write("regimes.csv", [&] { return regimes_csv(sweeps, thresholds); });
  context.write("thresholds.csv", [&] { return thresholds_csv(thresholds); });
  context.write("trajectories.csv", [&] { return trajectories_csv(sweeps); });

  toml::table summary{{"g", kTableGravity}, {"omega", kTableOmega}};
  toml::table failed;
  for (std::string_view method : {std::string_view("exact"), kTableSteppers[0], kTableSteppers[1]})
    failed.insert(method, static_cast<std::int64_t>(failures(sweeps, method)));
  failed.insert("first", first_failure(sweeps));
  summary.insert("diagram_failures", failed);
  summary.insert("e_0_5", table_thresholds_summary(thresholds[0]));
  summary.insert("e_0_8", table_thresholds_summary(thresholds[1]));
  return toml::table{{"vibrating_table", summary}};
}

const Experiment kVibratingTableExperiment{
    "vibrating_table",
    "The ball on a vibrating table: bifurcation diagrams and period-1 thresholds of every method",
    &run_vibrating_table};

}  // namespace impact::vibrating_table
