// The campaign of experiments/error_analysis: random scenes (u0, v0, f, COR, h, T over wide ranges,
// extreme ones included), each run by direct, fb_newton, moreau_jean and direct_located and
// compared, grid time by grid time, with the exact solution; every bound and identity of
// paper_notes/error_analysis.md (error_bounds.hpp) that applies to a run is checked on it. A
// proved bound that a run breaks is a violation (a failed proof); a conjecture's checks are counted
// apart. Each check also gives measured / bound, summarised as median and worst.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/run/scene.hpp"

namespace impact::error_analysis {

// The families of scenes, each aimed at statements of error_analysis.md:
//   zeno    f < 0 with a COR (Statement 3, and 2 at the first impact)
//   single  f >= 0 with a COR: at most one impact (Statement 2)
//   no_cor  f <= 0 without COR (Statements 2 and 4)
//   forced  f(t) = f + a sin(omega t + phase), with or without COR (Statement 1)
enum class CampaignKind { zeno, single, no_cor, forced };
std::string_view kind_name(CampaignKind kind);

struct CampaignScene {
  CampaignKind kind = CampaignKind::zeno;
  Scene scene;  // method: direct (the campaign runs each scheme on it)
};

// `count` scenes in the proportions zeno 1/3, single 1/6, no_cor 1/4, forced 1/4, drawn from a
// generator seeded with `seed` (splitmix64: the same scenes on every machine).
std::vector<CampaignScene> campaign_scenes(std::size_t count, std::uint64_t seed);

// A run on its grid: s[l] the state at t_l, N[l] the force of the step that ended at t_l (N[0] =
// 0).
struct Trace {
  std::vector<State> s;
  std::vector<double> N;
  bool failed = false;      // the scheme reported a numerical failure (no states then)
  double first_impact = 0;  // reference_trace: the first impact time (+infinity without one)
};
Trace run_trace(const Scene& scene);
// The exact solution (ReferenceSolution) at every grid time.
Trace reference_trace(const Scene& scene);

// One check of one run. A bound: a violation when measured > bound + allowance; a lower bound
// (lower = true): when measured < bound - allowance. `allowance` is the rounding the run's numbers
// carry (error_analysis.md, "Rounding"), never a margin on the statement.
struct Check {
  std::string name;  // "<statement>.<scheme>.<quantity>", e.g. "s3.direct.sup"
  std::size_t scene = 0;
  double h = 0;
  double measured = 0, bound = 0, allowance = 0;
  bool lower = false;
  double x = 0;  // the statement's variable (theta, sigma, the impact k); NaN when none
  // The signed quantity the check is about, where the figures want it (du, dv, the effective
  // COR W / V); NaN elsewhere.
  double value = std::numeric_limits<double>::quiet_NaN();
  bool violated() const {
    return lower ? measured < bound - allowance : measured > bound + allowance;
  }
  // measured / bound (bound / measured for a lower bound); for an identity or an exact result
  // (bound 0), measured / allowance; NaN where the bound is below the allowance (rounding).
  double ratio() const;
};

struct CheckSummary {
  std::string name;
  bool conjecture = false;  // checked, but not proved (error_analysis.md says which)
  // An identity or an exact result (every bound 0): its ratios are measured / allowance, the
  // error in units of the rounding allowance.
  bool identity = false;
  std::size_t runs = 0, violations = 0;
  double median_ratio = 0, worst_ratio = 0;  // over the runs with a ratio
};

struct CampaignOptions {
  std::size_t scenes = 4800;
  std::uint64_t seed = 20130601;
};

struct CampaignResult {
  std::size_t scenes = 0, runs = 0, failed_runs = 0;
  std::vector<Check> checks;
  std::vector<CheckSummary> summaries;  // one per check name, in a fixed order
};
// Whether a check name is a conjecture's.
bool is_conjecture(std::string_view name);

}  // namespace impact::error_analysis
