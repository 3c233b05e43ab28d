// The checks of the campaign (error_campaign.hpp), one function per statement of
// paper_notes/error_analysis.md, on one scene's runs: the exact solution and each scheme's trace on
// the grid.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "analysis/error_analysis/error_campaign.hpp"
#include "impact/model/model.hpp"

namespace impact::error_analysis {

// The rounding a run's numbers carry (error_analysis.md, "Rounding"), from the scene's scales:
// U = max |u - phi|, V = max |v|, F = |f| + |a| over the exact run, T and n = T / h.
struct Rounding {
  double position = 0;  // a closed-form flight (direct, fb_newton, direct_located)
  double velocity = 0;
  double stepped_position = 0;  // moreau_jean, whose increments accumulate one rounding per step
  double stepped_velocity = 0;
  double rebound = 0;  // a velocity from (4-2), v = 2 (phi - u^l) / h - v^l: position * 2 / h
  double kicks = 0;    // fb_newton: the velocity its smoothing added over the run (a posteriori)
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
  // Whether step l of direct (smoothing false) or fb_newton (true) is a contact step: it ends on
  // the floor with a contact force; an impact's step: also its flight from t_l reaches the floor
  // within it (constant f); and the first impact's step.
  bool contact_step(const Trace& t, std::size_t l, bool smoothing) const;
  bool impact_step(const Trace& t, std::size_t l, bool smoothing) const;
  std::optional<std::size_t> first_impact_step(const Trace& t, bool smoothing) const;
};

// The velocity fb_newton's smoothing may add in free flight in step l (Lemma 1.3), from the exact
// gap at t_{l+1}.
double kick(const SceneRuns& r, std::size_t l);
// The kicks of the steps before grid index `end` (Lemma 1.3): the velocity they add, and the
// position by t_end. Rounded, a kick is at most kKickRounding times its exact value.
// Newton's last update rounds to the nearest double: an update below half an ulp of the gap leaves
// it (no kick), a larger one lands within an ulp of the root, so a kick, at least ulp(gap) / h,
// is off by at most 2 ulp(gap) / h: at most 3 times its exact value (error_analysis.md,
// "Rounding").
inline constexpr double kKickRounding = 3;
struct KickSum {
  double velocity = 0, position = 0;
};
KickSum kicks_before(const SceneRuns& r, std::size_t end);

// Statement 3 on one run, impact by impact (f < 0, a COR): the landing time's error
// delta_k = t_k^h - t_k with Theorem 3.1's bound and the value its proof's identity gives from
// the run's own thetas, and the relaunch speed's error eps_k = W_k - e V_k likewise; the rounding
// each carries.
struct ImpactRecord {
  std::int64_t k = 0;
  double theta = 0;
  double delay = 0, delay_bound = 0, delay_round = 0, delay_identity = 0, delay_identity_round = 0;
  bool relaunched = false;  // the scheme bounced off (else it rests from this impact on)
  double speed = 0, speed_bound = 0, speed_identity = 0, speed_identity_round = 0;
};
struct BouncingRun {
  std::vector<ImpactRecord> impacts;
  std::optional<double> rest;  // the scheme's rest s_K, when it rests before T (Theorem 3.3)
  double rest_round = 0;
  std::int64_t impacts_before_rest = 0;
};
BouncingRun bouncing_run(const SceneRuns& r, const Trace& t, const Rounding& rounding,
                         bool smoothing = false);

void check_flight(const SceneRuns& r, std::vector<Check>& out);   // Statement 1
void check_impact(const SceneRuns& r, std::vector<Check>& out);   // Statement 2
void check_no_cor(const SceneRuns& r, std::vector<Check>& out);   // Statement 4
void check_zeno(const SceneRuns& r, std::vector<Check>& out);     // Statement 3
void check_located(const SceneRuns& r, std::vector<Check>& out);  // exactness of the variant

// A check named `name` on the run's scene.
// x: the statement's variable at this check (theta, sigma, the impact k), NaN when none.
Check make_check(const SceneRuns& r, std::string name, double measured, double bound,
                 double allowance, double x = std::numeric_limits<double>::quiet_NaN(),
                 bool lower = false);

}  // namespace impact::error_analysis
