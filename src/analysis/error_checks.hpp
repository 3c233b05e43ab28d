// The checks of the campaign (error_campaign.hpp), one function per statement of
// paper_notes/error_analysis.md, on one scene's runs: the exact solution and each scheme's trace on
// the grid.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/error_campaign.hpp"
#include "impact/model.hpp"

namespace impact {

// The rounding a run's numbers carry (error_analysis.md, "Rounding"), from the scene's scales:
// U = max |u - phi|, V = max |v|, F = |f| + |a| over the exact run, T and n = T / h.
struct Rounding {
  double position = 0;  // a closed-form flight (direct, fb_newton, direct_located)
  double velocity = 0;
  double stepped_position = 0;  // moreau_jean, whose increments accumulate one rounding per step
  double stepped_velocity = 0;
  double rebound = 0;  // a velocity from (4-2), v = 2 (phi - u^l) / h - v^l: position * 2 / h
  double time(double speed) const;  // a floor crossing at this speed
};
Rounding rounding_of(const Scene& scene, const Trace& exact);

// One scene's runs.
struct SceneRuns {
  const CampaignScene& scene;
  std::size_t index;
  Trace exact;
  std::optional<double> V1;  // the exact first impact's speed (constant force)
  Trace direct, fb_newton, moreau_jean, located;
  Rounding rounding;
  double eps = 0;                                   // fb_newton's smoothing
  double cor() const;                               // e: the COR, or 1 without one
  double gap(const Trace& t, std::size_t l) const;  // u^l - phi
  // The first contact step of a run (is_contact_step), or nullopt.
  std::optional<std::size_t> first_contact(const Trace& t) const;
  // The first contact step in which the run's own flight from t_l reaches the floor (the impact's
  // step, constant f), or nullopt.
  std::optional<std::size_t> first_crossing(const Trace& t) const;
};

// The velocity fb_newton's smoothing may add in free flight in step l (Lemma 1.3), from the exact
// gap at t_{l+1}.
double kick(const SceneRuns& r, std::size_t l);
// The kicks of the steps before grid index `end`, with their rounding: the velocity they add, and
// the position by t_end.
struct KickSum {
  double velocity = 0, position = 0;
};
KickSum kicks_before(const SceneRuns& r, std::size_t end);

void check_flight(const SceneRuns& r, std::vector<Check>& out);   // Statement 1
void check_impact(const SceneRuns& r, std::vector<Check>& out);   // Statement 2
void check_no_cor(const SceneRuns& r, std::vector<Check>& out);   // Statement 4
void check_zeno(const SceneRuns& r, std::vector<Check>& out);     // Statement 3
void check_located(const SceneRuns& r, std::vector<Check>& out);  // exactness of the variant

// A check named `name` on the run's scene.
Check make_check(const SceneRuns& r, std::string name, double measured, double bound,
                 double allowance, bool lower = false);

}  // namespace impact
