// Analysis of a run for Section 5.2 (Figures 3 and 4): when the particle comes to rest, how much
// energy each impact removes, and how far two methods' trajectories are apart. Contact steps and
// episodes are those of impact/model/contact.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "impact/model/contact.hpp"
#include "impact/model/model.hpp"
#include "impact/run/scene.hpp"

namespace impact {

// One row of a run: the state at t_l, N^{l-1} (the CSV convention, paper_notes/reading.md) as the
// method's solve gives it (scheme_force of model.hpp: with a COR, direct's and fb_newton's N^l of
// (4-3), which the claims about (4-3) and Figures 3 and 4 read, not the impulse the N channel
// carries) and E.
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

struct RestAnalysis {
  std::vector<ContactEpisode> episodes;
  // rest_time() of contact.hpp: t_{l+1} for the first step l of a final episode that lasts to T
  // and at least kMinRestSteps steps; nullopt when the particle is still bouncing at T.
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
  RestObserver(const Model& model, const Grid& grid)
      : model_(model), grid_(grid), contacts_(model, grid.h) {}
  void operator()(std::int64_t l, const State& s, const StepInfo& info);
  RestAnalysis result() const;

 private:
  Model model_;
  Grid grid_;
  ContactDetector contacts_;
  State previous_;
  double energy_initial_ = 0, energy_final_ = 0, energy_sum_ = 0;
};

// Runs the scene's method through a RestObserver.
RestAnalysis analyse_rest(const Scene& scene);

}  // namespace impact
