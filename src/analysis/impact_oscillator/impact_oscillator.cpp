#include "analysis/impact_oscillator/impact_oscillator.hpp"

#include <cctype>
#include <cmath>
#include <sstream>
#include <string>

#include "analysis/impact_oscillator/oscillator_law.hpp"
#include "analysis/impact_oscillator/oscillator_orbits.hpp"
#include "impact/ensemble/processor.hpp"
#include "impact/format.hpp"

namespace impact::impact_oscillator {

namespace {

// The counterexample to the cos-only phase: omega < 1, where gamma > 0 and acos picks the other
// sign of omega t0 (paper_notes/impact_oscillator.md, section 2).
const Oscillator kLowFrequency{0.8, 0.8, 0.5};

// The runs' thresholds: the period doubling bisected to 1e-10 in these brackets, the saddle-node
// extrapolated from these offsets on its stable side.
constexpr double kBisectionTolerance = 1e-10;
const std::vector<double> kSaddleNodeOffsets{1e-6, 2e-6, 4e-6, 8e-6};

std::string impact_rows(const char* runner, const Oscillator& o, const std::vector<Event>& events) {
  std::ostringstream out;
  int k = 0;
  for (const Event& e : events)
    if (e.kind == EventKind::impact)
      out << runner << ',' << ++k << ',' << round_trip(e.t) << ',' << round_trip(-e.v_before) << ','
          << round_trip(impact_phase(e.t, o.omega)) << '\n';
  return out.str();
}

toml::table check_table(const OrbitCheck& c) {
  return toml::table{{"V", c.V},
                     {"phase", c.phase},
                     {"V_error", c.V_error},
                     {"phase_error", c.phase_error},
                     {"impacts", static_cast<std::int64_t>(c.impacts)}};
}

// One step of the impact map from (phase/omega, V): how far the next impact is from the orbit's.
toml::table one_step_from(const Oscillator& o, const PeriodOneOrbit& orbit, double omega_t0) {
  const auto next = impact_map(o, {omega_t0 / o.omega, orbit.V}, 10 * orbit.T);
  return toml::table{
      {"omega_t0", omega_t0},
      {"next_V_error", next ? next->V - orbit.V : std::nan("")},
      {"next_time_error", next ? next->t - (omega_t0 / o.omega + orbit.T) : std::nan("")}};
}

// Every number of the table as `path_to_key = value` (dots and other characters as '_'), but
// those whose name is longer than 45 characters: gnuplot cuts names at 50, and plot.gp reads
// none of them.
std::string gnuplot_values(const toml::table& table, const std::string& prefix) {
  std::string text;
  for (const auto& [key, node] : table) {
    std::string name = prefix + std::string(key.str());
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    if (const toml::table* t = node.as_table())
      text += gnuplot_values(*t, name + "_");
    else if (const auto x = node.value<double>(); x && node.is_number() && name.size() <= 45)
      text += name + " = " + (std::isfinite(*x) ? round_trip(*x) : std::string("NaN")) + "\n";
  }
  return text;
}

}  // namespace

toml::table orbit_summary(const ExperimentContext& context) {
  const Oscillator& o = kAcceptance;
  const PeriodOneOrbit orbit = *period_one_orbit(o);
  const OrbitCheck reference = check_run(o, kAcceptanceStart, kAcceptanceT, Runner::reference);
  const OrbitCheck event_driven =
      check_run(o, kAcceptanceStart, kAcceptanceT, Runner::event_driven);
  context.write("acceptance_impacts.csv", [&] {
    return "runner,k,t,V,phase\n" +
           impact_rows("reference", o, run_track(o, kAcceptanceStart, kAcceptanceT).events) +
           impact_rows("event_driven", o,
                       event_driven_events(o, kAcceptanceStart, kAcceptanceT, 1.0));
  });
  const double trace = orbit_trace(o, orbit.V);
  const auto J = orbit_jacobian(o, orbit);
  const auto D = map_jacobian_by_differences(o, orbit, 1e-6);
  double fd = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) fd = std::fmax(fd, std::fabs(J[i][j] - D[i][j]));
  const PeriodOneOrbit low = *period_one_orbit(kLowFrequency);
  return toml::table{
      {"gamma", orbit.gamma},
      {"T", orbit.T},
      {"c_s", orbit.c_s},
      {"r_minus", orbit.r_minus},
      {"V", orbit.V},
      {"phase", orbit.t0},
      {"omega_t0", orbit.phase},
      {"omega_t0_acos", orbit.acos_phase},
      {"trace", trace},
      {"multiplier", leading_multiplier(trace, o.r)},
      {"jacobian_det_minus_r2", J[0][0] * J[1][1] - J[0][1] * J[1][0] - o.r * o.r},
      {"jacobian_trace_minus_formula", J[0][0] + J[1][1] - trace},
      {"jacobian_minus_differences", fd},
      {"reference", check_table(reference)},
      {"event_driven", check_table(event_driven)},
      {"low_frequency", toml::table{{"omega", kLowFrequency.omega},
                                    {"r", kLowFrequency.r},
                                    {"sigma", kLowFrequency.sigma},
                                    {"V", low.V},
                                    {"atan2", one_step_from(kLowFrequency, low, low.phase)},
                                    {"acos", one_step_from(kLowFrequency, low, low.acos_phase)}}}};
}

std::vector<double> branch_values(SweepParameter parameter) {
  return parameter == SweepParameter::sigma ? parameter_grid(-1.75, -0.10, 0.05)
                                            : parameter_grid(2.15, 4.20, 0.05);
}

std::vector<double> event_driven_branch_values(SweepParameter parameter) {
  return parameter == SweepParameter::sigma ? std::vector<double>{-1.7, -1.3, -0.9, -0.5, -0.1}
                                            : std::vector<double>{2.2, 2.8, 3.4, 4.0};
}

toml::table branch_summary(const ExperimentContext& context, SweepParameter parameter) {
  const bool sigma = parameter == SweepParameter::sigma;
  const auto oscillator = [&](double x) {
    return sigma ? Oscillator{kOmega, kRestitution, x} : Oscillator{x, kRestitution, kSigma};
  };
  std::vector<OrbitCheck> reference, event_driven;
  double det = 0;
  for (double x : branch_values(parameter)) {
    reference.push_back(check_branch_point(oscillator(x), Runner::reference));
    const auto J = orbit_jacobian(reference.back().o, reference.back().orbit);
    det = std::fmax(det,
                    std::fabs(J[0][0] * J[1][1] - J[0][1] * J[1][0] - kRestitution * kRestitution));
  }
  for (double x : event_driven_branch_values(parameter))
    event_driven.push_back(check_branch_point(oscillator(x), Runner::event_driven));
  context.write(sigma ? "branch_sigma.csv" : "branch_omega.csv", [&] {
    std::ostringstream out;
    out << "runner,parameter,formula_V,formula_phase,multiplier,impacts,V,phase,V_error,"
           "phase_error\n";
    for (const auto* list : {&reference, &event_driven})
      for (const OrbitCheck& c : *list)
        out << (list == &reference ? "reference" : "event_driven") << ','
            << round_trip(sigma ? c.o.sigma : c.o.omega) << ',' << round_trip(c.orbit.V) << ','
            << round_trip(c.orbit.t0) << ',' << round_trip(c.multiplier) << ',' << c.impacts << ','
            << round_trip(c.V) << ',' << round_trip(c.phase) << ',' << round_trip(c.V_error) << ','
            << round_trip(c.phase_error) << '\n';
    return out.str();
  });
  const BranchAgreement a = agreement(reference), b = agreement(event_driven);
  double largest_multiplier = 0;
  for (const OrbitCheck& c : reference)
    largest_multiplier = std::fmax(largest_multiplier, c.multiplier);
  return toml::table{{"points", static_cast<std::int64_t>(a.points)},
                     {"largest_multiplier", largest_multiplier},
                     {"reference_max_V_error", a.V},
                     {"reference_max_phase_error", a.phase},
                     {"event_driven_points", static_cast<std::int64_t>(b.points)},
                     {"event_driven_max_V_error", b.V},
                     {"event_driven_max_phase_error", b.phase},
                     {"jacobian_max_det_minus_r2", det}};
}

toml::table thresholds_summary() {
  const double sn = saddle_node_sigma(kOmega, kRestitution);
  const double pd = period_doubling_sigma(kOmega, kRestitution);
  const double sn_runs =
      extrapolate_saddle_node_sigma(kOmega, kRestitution, sn, kSaddleNodeOffsets);
  const double pd_runs =
      bisect_period_doubling_sigma(kOmega, kRestitution, pd - 1e-3, pd + 1e-3, kBisectionTolerance);
  const double sn_w = *saddle_node_omega(kSigma, kRestitution, kOmega, 1.5);
  const double pd_w = *period_doubling_omega(kSigma, kRestitution, kOmega, 6.0);
  const double sn_w_runs =
      extrapolate_saddle_node_omega(kSigma, kRestitution, sn_w, kSaddleNodeOffsets);
  const double pd_w_runs = bisect_period_doubling_omega(kSigma, kRestitution, pd_w - 4e-3,
                                                        pd_w + 4e-3, kBisectionTolerance);
  return toml::table{{"sigma_saddle_node", sn},
                     {"sigma_saddle_node_runs", sn_runs},
                     {"sigma_saddle_node_shift", sn_runs - sn},
                     {"sigma_period_doubling", pd},
                     {"sigma_period_doubling_runs", pd_runs},
                     {"sigma_period_doubling_shift", pd_runs - pd},
                     {"sigma_grazing", grazing_sigma(kOmega)},
                     {"omega_saddle_node", sn_w},
                     {"omega_saddle_node_runs", sn_w_runs},
                     {"omega_saddle_node_shift", sn_w_runs - sn_w},
                     {"omega_period_doubling", pd_w},
                     {"omega_period_doubling_runs", pd_w_runs},
                     {"omega_period_doubling_shift", pd_w_runs - pd_w}};
}

toml::table run_impact_oscillator(const ExperimentContext& context,
                                  const std::optional<TimingRule>& timing) {
  toml::table summary{{"omega", kOmega}, {"r", kRestitution}, {"sigma", kSigma}};
  summary.insert("orbit", orbit_summary(context));
  summary.insert("branch_sigma", branch_summary(context, SweepParameter::sigma));
  summary.insert("branch_omega", branch_summary(context, SweepParameter::omega));
  summary.insert("thresholds", thresholds_summary());
  summary.insert("diagram", diagram_summary(context));
  summary.insert("grazing", grazing_summary(context));
  summary.insert("chatter", chatter_summary(context));
  summary.insert("work_precision", work_precision_summary(context, timing));
  context.write("values.gp", [&] {
    std::string text = "# The summary's numbers as gnuplot variables, for plot.gp.\n" +
                       gnuplot_values(summary, "");
    if (timing) text += "processor = \"" + this_processor().describe() + "\"\n";
    return text;
  });
  return toml::table{{"impact_oscillator", summary}};
}

toml::table run_impact_oscillator(const ExperimentContext& context) {
  return run_impact_oscillator(
      context, context.writes() ? std::optional<TimingRule>(TimingRule{}) : std::nullopt);
}

const Experiment kImpactOscillatorExperiment{
    "impact_oscillator",
    "The impact oscillator: period-one orbits, thresholds, grazing, chatter and work-precision",
    &run_impact_oscillator};

}  // namespace impact::impact_oscillator
