#include "analysis/stability/stability_study.hpp"

#include <map>

#include "analysis/stability/stability_cases.hpp"
#include "analysis/stability/stability_smoothing.hpp"
#include "analysis/stability/stability_stiffness.hpp"
#include "analysis/stability/stability_table.hpp"
#include "impact/ensemble/processor.hpp"

namespace impact::stability {
namespace {

// The runs the summary names: fb_newton keeps a particle at rest on a floor at 1e6 at h = 1e-9
// (the far-floor safeguard), and direct's COR law raises the energy when f > 0 (h = 1e-3).
constexpr int kFarRestLogH = -9, kPushLogH = -3;

// The rows of the stability map: each case's data (gnuplot enhanced text; SI units, phi = 0 unless
// given, g = -9.80665). The case names are for the CSV files and the tables.
const std::map<std::string, std::string> kCaseLabels = {
    {"paper_f0", "Fig. 3: u_0 = 5, v_0 = -1, f = 0"},
    {"paper_gravity", "Fig. 4: u_0 = 5, v_0 = -1, f = g"},
    {"cor0", "Fig. 4 with COR = 0"},
    {"cor1", "Fig. 4 with COR = 1"},
    {"cor_0.999", "u_0 = 0.01, v_0 = 0, f = g, COR = 0.999"},
    {"bounces_1e4", "u_0 = 10^{-4}, v_0 = 0, f = g"},
    {"v0_-1e8", "u_0 = 1, v_0 = -10^8, f = 0"},
    {"v0_-1e8_gravity", "u_0 = 1, v_0 = -10^8, f = g"},
    {"f_-1e8", "u_0 = 1, v_0 = 0, f = -10^8"},
    {"f_+1e8", "u_0 = 1, v_0 = -10^8, f = +10^8"},
    {"f_+9.8", "u_0 = 0.01, v_0 = -1, f = -g (upward)"},
    {"f_+9.8_cor1", "u_0 = 0.01, v_0 = -1, f = -g, COR = 1"},
    {"contact_v0<0", "u_0 = {/Symbol f}, v_0 = -1, f = g"},
    {"contact_v0=0", "u_0 = {/Symbol f}, v_0 = 0, f = g (resting)"},
    {"contact_v0>0", "u_0 = {/Symbol f}, v_0 = +1, f = g"},
    {"contact_f0", "u_0 = {/Symbol f}, v_0 = 0, f = 0"},
    {"phi_1e6", "{/Symbol f} = 10^6, u_0 = {/Symbol f} + 5, v_0 = -1, f = g"},
    {"phi_1e6_near", "{/Symbol f} = 10^6, u_0 = {/Symbol f} + 10^{-3}, v_0 = -1, f = g"},
    {"phi_1e6_rest", "{/Symbol f} = 10^6, u_0 = {/Symbol f}, v_0 = 0, f = g"},
};

std::string gnuplot_labels() {
  std::string cases = "set_case_tics = \"set ytics (";
  const auto& list = extreme_cases();
  for (std::size_t c = 0; c < list.size(); ++c) {
    const auto label = kCaseLabels.find(list[c].name);
    cases += (c ? ", " : "") + std::string("'") +
             (label == kCaseLabels.end() ? list[c].name : label->second) + "' " + std::to_string(c);
  }
  cases += ")\"\n";
  std::string steppers = "set_stepper_tics = \"set ytics (";
  const auto& st = stiffness_steppers();
  for (std::size_t i = 0; i < st.size(); ++i)
    steppers += (i ? ", " : "") + std::string("'") + st[i].name +
                (st[i].implicit ? " (impl.)" : "") + "' " + std::to_string(i);
  steppers += ")\"\n";
  return cases + steppers;
}

toml::table outcome_counts(const CaseMap& map) {
  toml::table outcomes;
  for (const auto& method : stability_methods()) {
    toml::table t;
    for (Outcome o : {Outcome::ok, Outcome::inaccurate, Outcome::energy_grows, Outcome::failure,
                      Outcome::non_finite, Outcome::over_budget, Outcome::rejected})
      t.insert(outcome_name(o), map.count(method, o));
    outcomes.insert(method, t);
  }
  return outcomes;
}

// The extreme cases: the map, or only the two runs the summary names.
void add_cases(const ExperimentContext& context, const StabilityStudyOptions& options,
               toml::table& summary) {
  StabilityRun far_rest, push;
  if (options.case_map) {
    const CaseMap map = CaseMap::run();
    context.write("cases.csv", [&] { return map.csv(); });
    context.write("map_cases.dat", [&] { return map.dat(); });
    context.write("table.md", [&] { return stability_table(map); });
    summary.insert("outcomes", outcome_counts(map));
    far_rest = map.at("fb_newton", "phi_1e6_rest", kFarRestLogH);
    push = map.at("direct", "f_+9.8_cor1", kPushLogH);
  } else {
    far_rest = run_extreme_case("phi_1e6_rest", "fb_newton", kFarRestLogH);
    push = run_extreme_case("f_+9.8_cor1", "direct", kPushLogH);
  }
  summary.insert("fb_newton_phi_1e6_rest_h_1e-9",
                 toml::table{{"max_energy_rise", far_rest.check.max_energy_rise},
                             {"error_u", far_rest.check.error_u},
                             {"max_iterations", far_rest.check.max_iterations}});
  summary.insert("direct_cor1_push_h_1e-3",
                 toml::table{{"max_energy_rise", push.check.max_energy_rise},
                             {"energy_rises", push.check.energy_rises}});
}

void add_smoothing(const ExperimentContext& context, toml::table& summary) {
  const SmoothingMap map = SmoothingMap::run();
  context.write("eps.csv", [&] { return map.csv(); });
  context.write("map_eps.dat", [&] { return map.dat(); });
  summary.insert("eps", toml::table{{"runs", static_cast<std::int64_t>(map.runs.size())},
                                    {"failures", map.failures},
                                    {"energy_violations", map.energy_violations},
                                    {"max_iterations", map.max_iterations},
                                    {"max_mean_iterations", map.max_mean_iterations}});
}

toml::table stepper_summary(const StiffnessStudy& study, const std::string& name, bool maps) {
  const ContactResolution& c6 = study.bounce(name, 6).contact;
  const ContactResolution& c12 = study.bounce(name, 12).contact;
  const StabilityCheck& b6 = study.bounce(name, 6).run.run.check;
  const StabilityCheck& b12 = study.bounce(name, 12).run.run.check;
  toml::table t{{"penetration_1e6", c6.penetration},
                {"penetration_1e12", c12.penetration},
                {"duration_1e6", c6.duration},
                {"duration_1e12", c12.duration},
                {"impulse_1e12", c12.impulse},
                {"bounce_ode_steps_1e6", b6.work},
                {"bounce_ode_steps_1e12", b12.work},
                {"bounce_error_u_1e12", b12.error_u},
                {"rest_ode_steps_1e6", study.rest(name, 6).run.run.check.work}};
  if (maps) t.insert("rest_largest_c_N", study.rest_limit(name));
  return t;
}

// Penalty over c_N: every c_N and the c_N x h map, or only the c_N the summary names.
void add_stiffness(const ExperimentContext& context, const StabilityStudyOptions& options,
                   toml::table& summary) {
  std::vector<int> all;
  for (int k = kLogStiffnessMin; k <= kLogStiffnessMax; ++k) all.push_back(k);
  const bool maps = options.stiffness_maps;
  const StiffnessStudy study =
      maps ? StiffnessStudy::run(all, all) : StiffnessStudy::run({6, 12}, {6});
  context.write("stiff.csv", [&] { return study.csv(); });
  context.write("map_stiff.dat", [&] { return study.dat(); });
  if (maps) {
    const PenaltyStepMap step_map = PenaltyStepMap::run();
    context.write("penalty_h.csv", [&] { return step_map.csv(); });
    context.write("map_penalty.dat", [&] { return step_map.dat(); });
  }
  toml::table penalty;
  for (const OdeStepper& st : stiffness_steppers())
    penalty.insert(st.name, stepper_summary(study, st.name, maps));
  summary.insert("penalty", penalty);
}

}  // namespace

toml::table run_stability(const ExperimentContext& context) {
  return run_stability(context, StabilityStudyOptions{});
}

toml::table run_stability(const ExperimentContext& context, const StabilityStudyOptions& options) {
  toml::table summary;
  add_cases(context, options, summary);
  if (options.smoothing_map) add_smoothing(context, summary);
  add_stiffness(context, options, summary);
  context.write("labels.gp", gnuplot_labels);
  // The stiff runs' wall times are this processor's: their figure names it.
  context.write_text("processor.txt", this_processor().describe() + "\n");
  return summary;
}

const Experiment kStabilityExperiment{
    "stability",
    "Numerical stability: every method on extreme cases over h = 1e-9..1, fb_newton over eps, "
    "penalty over c_N",
    &run_stability};

}  // namespace impact::stability
