// Lemma 3 (Section 4): the a priori bounds on max|v^l| and max|u^l|, the energy inequality
// E^{l+1} <= E^l (4-6) and the bound on h sum N^l after (4-9), measured on the 144 runs of
// lemma3_sweep() (direct scheme, no COR, phi = 0, T = 2).
//
// Usage: exp_lemma3 RESULTS_DIR. Writes
//   runs.csv      one row per run: data, measured maxima, bounds, ratios, energy counts
//   summary.toml  the sweep's key numbers (the keys of experiments/lemma3/reference.toml)
#include <toml++/toml.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>

#include "analysis/bounds.hpp"
#include "impact/output.hpp"

namespace {

using impact::Lemma3Run;

void write_runs(const std::string& path, const std::vector<Lemma3Run>& runs) {
  impact::AtomicFile file(path);
  std::FILE* out = file.stream();
  std::fprintf(out,
               "index,h,f,u0,v0,max_v,max_u,impulse,velocity_change,T,bound_v,bound_u,"
               "bound_u_corrected,bound_impulse,ratio_v,ratio_u,ratio_u_corrected,ratio_impulse,"
               "energy_increases,energy_violations,energy_max_increase_over_tolerance,"
               "printed_4_7_violations\n");
  int index = 0;
  for (const Lemma3Run& r : runs) {
    const auto& m = r.measured;
    const auto& b = r.bounds;
    std::fprintf(
        out,
        "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
        "%.17g,%.17g,%.17g,%.17g,%.17g,%lld,%lld,%.17g,%lld\n",
        ++index, r.h, r.f, r.u0, r.v0, m.max_v, m.max_u, m.impulse, m.velocity_change, m.T,
        b.velocity, b.displacement, b.displacement_corrected, b.impulse,
        impact::bound_ratio(m.max_v, b.velocity), impact::bound_ratio(m.max_u, b.displacement),
        impact::bound_ratio(m.max_u, b.displacement_corrected),
        impact::bound_ratio(m.impulse, b.impulse), static_cast<long long>(m.energy_increases),
        static_cast<long long>(m.energy_violations), m.max_energy_increase_over_tolerance,
        static_cast<long long>(m.printed_4_7_violations));
  }
  file.commit();
}

toml::table stats(const impact::RatioStats& r) {
  return toml::table{{"violations", r.violations},
                     {"min_ratio", r.min},
                     {"median_ratio", r.median},
                     {"max_ratio", r.max}};
}

toml::table summarize(const impact::Lemma3Summary& s) {
  return toml::table{
      {"runs", s.runs},
      {"T", impact::kLemma3SweepT},
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

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s RESULTS_DIR\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    const std::vector<Lemma3Run> runs = impact::lemma3_sweep();
    write_runs((dir / "runs.csv").string(), runs);
    impact::AtomicFile summary((dir / "summary.toml").string());
    std::ostringstream text;
    text << toml::table{{"lemma3", summarize(impact::summarize_lemma3(runs))}} << '\n';
    std::fputs(text.str().c_str(), summary.stream());
    summary.commit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_lemma3: %s\n", e.what());
    return 1;
  }
  return 0;
}
