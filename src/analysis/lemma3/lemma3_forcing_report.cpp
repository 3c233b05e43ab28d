#include "analysis/lemma3/lemma3_forcing_report.hpp"

#include <sstream>
#include <string_view>

#include "impact/output/csv.hpp"

namespace impact::lemma3 {

namespace {

// The case as one line of the summary: method and data (6 digits: they only name the case).
std::string case_text(const ForcingCase& c) {
  std::ostringstream text;
  text << c.method << ": f = " << c.f << ", a = " << c.amplitude << ", omega = " << c.omega
       << ", phase = " << c.phase << ", u0 = " << c.u0 << ", v0 = " << c.v0 << ", h = " << c.h;
  return text.str();
}

toml::table stats_table(const ForcingStats& s) {
  return toml::table{{"violations", s.violations},
                     {"zero_bound", s.zero_bound},
                     {"median_ratio", s.median},
                     {"max_ratio", s.max},
                     {"worst", case_text(s.worst)}};
}

toml::table method_table(const ForcingSummary& s) {
  toml::table velocity, printed, full;
  for (std::size_t i = 0; i < kForceReadings.size(); ++i) {
    const std::string_view name = reading_name(kForceReadings[i]);
    velocity.insert(name, stats_table(s.velocity[i]));
    printed.insert(name, stats_table(s.displacement[i]));
    full.insert(name, stats_table(s.displacement_full[i]));
  }
  const ForcedEnergySummary& e = s.energy;
  return toml::table{
      {"runs", s.runs},
      {"velocity_bound", velocity},
      {"displacement_bound_printed", printed},
      {"displacement_bound_full_T", full},
      {"proof_velocity_bound", stats_table(s.proof_velocity)},
      {"proof_displacement_bound", stats_table(s.proof_displacement)},
      {"energy",
       toml::table{{"steps", e.steps},
                   {"work_energy_rises", e.work_rises},
                   {"work_energy_max_rise_over_tolerance", e.max_work_rise_over_tolerance},
                   {"energy_rises", e.energy_rises},
                   {"energy_rise_runs", e.energy_rise_runs},
                   {"energy_max_rise", e.max_energy_rise}}},
  };
}

}  // namespace

toml::table forcing_summary(const std::vector<ForcingRun>& runs) {
  toml::table out = method_table(summarize_forcing(runs, ""));
  out.insert("T", kForcingT);
  // Per method only the counts: the two schemes solve the same step (C6).
  toml::table methods;
  for (std::string_view method : {"direct", "fb_newton"}) {
    const ForcingSummary s = summarize_forcing(runs, method);
    toml::table violations;
    for (std::size_t i = 0; i < kForceReadings.size(); ++i)
      violations.insert(reading_name(kForceReadings[i]), s.velocity[i].violations);
    methods.insert(method, toml::table{{"runs", s.runs},
                                       {"velocity_bound_violations", violations},
                                       {"proof_velocity_max_ratio", s.proof_velocity.max},
                                       {"work_energy_rises", s.energy.work_rises}});
  }
  out.insert("methods", methods);
  return out;
}

std::string forcing_runs_csv(const std::vector<ForcingRun>& runs) {
  std::ostringstream csv;
  csv << "index,method,f,amplitude,omega,phase,u0,v0,h,max_v,max_u,sup_f,int_abs_f,rms_f";
  for (ForceReading r : kForceReadings) {
    const std::string_view n = reading_name(r);
    csv << ",ratio_v_" << n << ",ratio_u_" << n << ",ratio_u_full_" << n;
  }
  csv << ",ratio_v_proof,ratio_u_proof,work_rises,energy_rises,energy_max_rise\n";
  int index = 0;
  for (const ForcingRun& r : runs) {
    csv << ++index << ',' << r.c.method;
    for (double x : {r.c.f, r.c.amplitude, r.c.omega, r.c.phase, r.c.u0, r.c.v0, r.c.h, r.max_v,
                     r.max_u, r.norms.sup, r.norms.integral, r.norms.rms})
      csv << ',' << round_trip(x);
    for (const ForcingRatios& q : r.readings)
      csv << ',' << round_trip(q.velocity) << ',' << round_trip(q.displacement) << ','
          << round_trip(q.displacement_full);
    csv << ',' << round_trip(r.proof_velocity) << ',' << round_trip(r.proof_displacement) << ','
        << r.energy.work_rises << ',' << r.energy.energy_rises << ','
        << round_trip(r.energy.max_energy_rise) << '\n';
  }
  return csv.str();
}

}  // namespace impact::lemma3
