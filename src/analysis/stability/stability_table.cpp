#include "analysis/stability/stability_table.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/markdown.hpp"

namespace impact::stability {
namespace {

// One letter per outcome, for the first table.
char letter(Outcome o) {
  switch (o) {
    case Outcome::ok:
      return 'o';
    case Outcome::inaccurate:
      return 'i';
    case Outcome::energy_grows:
      return 'E';
    case Outcome::failure:
      return 'F';
    case Outcome::non_finite:
      return 'N';
    case Outcome::over_budget:
      return 'B';
    case Outcome::rejected:
      return '-';
  }
  return '?';
}

std::string letters_table(const CaseMap& map) {
  std::string out =
      "Outcome per h = 1e-9, 1e-8, ..., 1 (one letter each): o ok, i inaccurate (error > 1% of "
      "the amplitude), E energy grows where the theory forbids it, F failure reported, "
      "N non-finite caught, B over the work budget, - rejected (penalty has no COR).\n\n"
      "| case | T | direct | fb_newton | moreau_jean | exact | penalty |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n";
  const auto& cases = extreme_cases();
  for (std::size_t c = 0; c < cases.size(); ++c) {
    out += "| " + cases[c].name + " | " + short_number(cases[c].T) + " |";
    for (const auto& method : stability_methods()) {
      std::string letters;
      for (const StabilityRun& run : map.row(method, c)) letters += letter(run.check.outcome);
      out += " `" + letters + "` |";
    }
    out += "\n";
  }
  return out;
}

// What one method did over the h sweep of one case.
struct RowSummary {
  int runs = 0, finished = 0, rises = 0, failed = 0, rejected = 0, iter_max = 0;
  double min_gap = INFINITY, max_rise = -INFINITY, iter_mean = 0, worst = 0, at_1e3 = NAN;
  bool bound = false;
};

RowSummary summarize(const std::vector<StabilityRun>& runs, const ExtremeCase& c) {
  RowSummary r;
  r.runs = static_cast<int>(runs.size());
  r.bound = runs.front().check.energy_bound;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const StabilityCheck& k = runs[i].check;
    if (k.outcome == Outcome::rejected) {
      ++r.rejected;
      continue;
    }
    const bool done = k.message.empty();
    r.finished += done;
    r.failed += k.outcome == Outcome::failure || k.outcome == Outcome::non_finite;
    r.min_gap = std::fmin(r.min_gap, k.min_gap);
    if (k.energy_bound && k.energy_rises > 0) ++r.rises;
    if (k.steps > 0) r.max_rise = std::fmax(r.max_rise, k.max_energy_rise);
    r.iter_max = std::max(r.iter_max, k.max_iterations);
    r.iter_mean = std::fmax(r.iter_mean, k.mean_iterations);
    if (done) {
      // Relative to the amplitude, or to the accuracy floor for a particle at rest.
      const double scale =
          std::fmax(k.amplitude, kAccuracyFloor / kAccuracy * std::fmax(1.0, std::fabs(c.phi)));
      const double rel = k.error_u / scale;
      r.worst = std::fmax(r.worst, rel);
      if (static_cast<int>(i) + kLogHMin == -3) r.at_1e3 = rel;
    }
  }
  return r;
}

std::string summary_row(const ExtremeCase& c, const std::string& method, const RowSummary& r) {
  if (r.rejected == r.runs)
    return "| " + c.name + " | " + method + " | rejected: no COR law | | | | | | | | |\n";
  return "| " + c.name + " | " + method + " | " + std::to_string(r.finished) + "/" +
         std::to_string(r.runs) + " | " + short_number(r.min_gap) + " | " +
         (r.bound ? std::to_string(r.rises) : std::string("n/a")) + " | " +
         short_number(r.max_rise) + " | " + std::to_string(r.iter_max) + " | " +
         short_number(r.iter_mean) + " | " + std::to_string(r.failed) + " | " +
         short_number(r.at_1e3) + " | " + short_number(r.worst) + " |\n";
}

std::string summary_table(const CaseMap& map) {
  std::string out =
      "\nPer case and method, over the 10 runs of the h sweep: runs that finished (all values "
      "finite), min(u - phi), runs with an energy rise beyond round-off (where the theory "
      "bounds it: direct, fb_newton, exact) and the largest rise, Newton iterations per step "
      "(fb_newton; penalty: ODE steps) max and largest mean, runs stopped by a failure, and "
      "max_l |u^l - u(t_l)| / amplitude at h = 1e-3 and at the worst h (a particle at rest, "
      "amplitude 0: relative to 1e-10 max(1, |phi|)). E excludes penalty's spring energy.\n\n"
      "| case | method | finished | min(u - phi) | E rises | max rise | iter. max | iter. mean "
      "| failed | rel. error h=1e-3 | worst rel. error |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  const auto& cases = extreme_cases();
  for (std::size_t c = 0; c < cases.size(); ++c)
    for (const auto& method : stability_methods())
      out += summary_row(cases[c], method, summarize(map.row(method, c), cases[c]));
  return out;
}

}  // namespace

std::string stability_table(const CaseMap& map) {
  return letters_table(map) + summary_table(map);
}

}  // namespace impact::stability
