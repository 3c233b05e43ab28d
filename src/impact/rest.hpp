// Analysis of a run for Section 5.2 (Figures 3 and 4): when the particle comes to rest, how much
// energy each impact removes, and how far two methods' trajectories are apart.
//
// A step (t_l, t_{l+1}] "ends in contact" when the pair (u^{l+1} - phi, N^l) of (4-3) is on its
// force branch, N^l > u^{l+1} - phi: the test the schemes themselves use to apply a COR
// (restitution.hpp, fb_newton.cpp). For `direct` it means N^l > 0 (a contact step ends at
// u^{l+1} = phi exactly); for `fb_newton`, whose smoothed pair near the floor has
// (u^{l+1} - phi) N^l = eps/2, it is the branch on which fb_newton applies the COR, so no length
// threshold is needed (a step that would end less than sqrt(eps/2), 2.2e-8 m for eps = 1e-15,
// above phi is already on it); for `exact` it means an impact in the step or resting (N = -f). A
// contact episode is a maximal run of consecutive contact steps: one impact (one step, or two when
// the scheme holds the particle on the floor) or, when it lasts to the end of the run, rest.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "impact/model.hpp"
#include "impact/scene.hpp"

namespace impact {

// One row of a run: the state at t_l, N^{l-1} (the CSV convention, paper_notes/reading.md) and E.
struct Sample {
  double t = 0, u = 0, v = 0, N = 0, E = 0;
};

// Runs the scene's method and keeps every step (T/h + 1 samples).
std::vector<Sample> record(const Scene& scene);

// max_l |a_l - b_l| of each channel; throws std::invalid_argument unless a and b have the same
// grid times.
struct ChannelDifference {
  double u = 0, v = 0, N = 0, E = 0;
};
ChannelDifference max_difference(const std::vector<Sample>& a, const std::vector<Sample>& b);

// What a recorded run says about energy and impulse: max_l |E^l - E^0| (0 for an energy-conserving
// run, Lemma 1), the total impulse h sum N^l (equal to v^n - v^0 - f T by (4-9) when every step
// obeys (4-1)), and the largest N^l with the time of its row.
struct RunStats {
  double energy_drift = 0, impulse = 0, peak_N = 0, peak_t = 0;
};
RunStats run_stats(const std::vector<Sample>& run, double h);

struct ContactEpisode {
  std::int64_t first_step = 0;  // l: the step (t_l, t_{l+1}] that starts the episode
  std::int64_t steps = 0;       // consecutive contact steps, l .. l + steps - 1
  // Fraction of step l flown before the floor, (u^l - phi) / (h |v^l|) for v^l < 0, else 0. The
  // direct scheme without COR rebounds with |v^l| (1 - 2 theta) and removes
  // N^l (u^l - phi) = 2 theta (1 - theta) (v^l)^2 + |f| theta h |v^l| by (4-6).
  double theta = 0;
  double speed_before = 0;   // |v^l|
  double energy_before = 0;  // E^l (4-5)
  double energy_after = 0;   // E at the end of the episode
};

// Shortest final episode that counts as rest: an impact of `direct` lasts one step, or two when
// theta > 1/2; with a COR every scheme impact lasts one step.
constexpr std::int64_t kMinRestSteps = 3;

struct RestAnalysis {
  std::vector<ContactEpisode> episodes;
  // t_{l+1} for the first step l of a final episode that lasts to T and at least kMinRestSteps
  // steps: the first grid time from which the particle never leaves the floor; nullopt when it is
  // still bouncing at T.
  std::optional<double> rest_time;
  std::int64_t impacts = 0;  // episodes before rest (all episodes when it does not rest)
  double energy_initial = 0, energy_final = 0;  // E^0 and E^n
  // Mean of E^l over l = 0..n: equal to E^0 when the graph of E is flat (the exact elastic
  // solution), smaller the earlier the energy is lost.
  double energy_mean = 0;
  double energy_loss() const { return energy_initial - energy_final; }
};

// Streams a run (an observer for simulate()) and builds its RestAnalysis in O(episodes) memory.
class RestObserver {
 public:
  RestObserver(const Model& model, const Grid& grid) : model_(model), grid_(grid) {}
  void operator()(std::int64_t l, const State& s, const StepInfo& info);
  RestAnalysis result() const;

 private:
  Model model_;
  Grid grid_;
  State previous_;
  bool previous_contact_ = false;
  double energy_sum_ = 0;
  RestAnalysis analysis_;
};

// Runs the scene's method through a RestObserver.
RestAnalysis analyse_rest(const Scene& scene);

}  // namespace impact
