#include "analysis/lemma3/lemma3.hpp"

#include <sstream>
#include <string>
#include <vector>

#include "analysis/lemma3/bounds.hpp"
#include "analysis/lemma3/lemma3_forcing.hpp"
#include "analysis/lemma3/lemma3_forcing_report.hpp"
#include "impact/output/csv.hpp"

namespace impact::lemma3 {

namespace {

std::string runs_csv(const std::vector<Lemma3Run>& runs) {
  std::ostringstream csv;
  csv << "index,h,f,u0,v0,max_v,max_u,impulse,velocity_change,T,bound_v,bound_u,"
         "bound_u_corrected,bound_impulse,ratio_v,ratio_u,ratio_u_corrected,ratio_impulse,"
         "energy_increases,energy_violations,energy_max_increase_over_tolerance,"
         "printed_4_7_violations\n";
  int index = 0;
  for (const Lemma3Run& r : runs) {
    const Lemma3Measurement& m = r.measured;
    const Lemma3Bounds& b = r.bounds;
    csv << ++index;
    for (double x :
         {r.h, r.f, r.u0, r.v0, m.max_v, m.max_u, m.impulse, m.velocity_change, m.T, b.velocity,
          b.displacement, b.displacement_corrected, b.impulse, bound_ratio(m.max_v, b.velocity),
          bound_ratio(m.max_u, b.displacement), bound_ratio(m.max_u, b.displacement_corrected),
          bound_ratio(m.impulse, b.impulse)})
      csv << ',' << round_trip(x);
    csv << ',' << m.energy_increases << ',' << m.energy_violations << ','
        << round_trip(m.max_energy_increase_over_tolerance) << ',' << m.printed_4_7_violations
        << '\n';
  }
  return csv.str();
}

toml::table stats(const RatioStats& r) {
  return toml::table{{"violations", r.violations},
                     {"min_ratio", r.min},
                     {"median_ratio", r.median},
                     {"max_ratio", r.max}};
}

toml::table summary(const Lemma3Summary& s) {
  return toml::table{
      {"runs", s.runs},
      {"T", kLemma3SweepT},
      {"velocity_bound", stats(s.velocity)},
      {"displacement_bound_printed", stats(s.displacement)},
      {"displacement_bound_corrected", stats(s.displacement_corrected)},
      {"impulse_claim", stats(s.impulse)},
      {"identity_4_9",
       toml::table{{"printed_max_residual", s.identity_printed_max_residual},
                   {"with_body_force_max_residual", s.identity_corrected_max_residual}}},
      {"printed_4_7_violation_runs", s.printed_4_7_violation_runs},
      {"energy_inequality",
       toml::table{{"steps", s.energy_steps},
                   {"increases", s.energy_increases},
                   {"violations_beyond_roundoff", s.energy_violations},
                   {"max_increase_over_tolerance", s.energy_max_increase_over_tolerance}}},
  };
}

}  // namespace

toml::table run_lemma3(const ExperimentContext& context) {
  const std::vector<Lemma3Run> runs = lemma3_sweep();
  context.write("runs.csv", [&] { return runs_csv(runs); });
  const std::vector<ForcingRun> forcing = run_forcing_sweep(full_forcing_sweep());
  context.write("forcing_runs.csv", [&] { return forcing_runs_csv(forcing); });
  return toml::table{{"lemma3", summary(summarize_lemma3(runs))},
                     {"lemma3_forcing", forcing_summary(forcing)}};
}

const Experiment kLemma3Experiment{
    "lemma3", "Lemma 3 (Section 4): a priori bounds, energy inequality and impulse bound",
    &run_lemma3};

}  // namespace impact::lemma3
