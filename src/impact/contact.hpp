// Contact steps and contact episodes of a run, for any method.
//
// A step (t_l, t_{l+1}] is a contact step when the pair (u^{l+1} - phi, N^l) of (4-3) is on its
// force branch, N^l > u^{l+1} - phi. For `direct` that is N^l > 0 (a contact step ends at
// u^{l+1} = phi exactly; a step that lands exactly on the floor with N^l = 0 is not one yet: its
// impulse comes in the next step, as in restitution.hpp). For `fb_newton`, whose smoothed pair
// near the floor has (u^{l+1} - phi) N^l = eps/2, it is the branch on which the smoothing pushes,
// with no length threshold (a step ending less than sqrt(eps/2), 2.2e-8 m for eps = 1e-15, above
// phi is already on it). For `moreau_jean`, which does not project, a step ending below the floor
// is one. For `exact`, a step with an impact or resting (N = -f).
//
// A contact episode is a maximal run of consecutive contact steps: one impact (one step, or two
// when a scheme holds the particle on the floor) or, when it lasts to the end of the run, rest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "impact/model.hpp"

namespace impact {

inline bool is_contact_step(const Model& model, const State& after, double contact_force) {
  return contact_force > after.u - model.phi;
}

struct ContactEpisode {
  std::int64_t first_step = 0;  // l: the step (t_l, t_{l+1}] that starts the episode
  double t_start = 0;           // t_l
  std::int64_t steps = 0;       // consecutive contact steps, l .. l + steps - 1
  // Fraction of step l flown before the floor along the straight line,
  // (u^l - phi) / (h |v^l|) for v^l < 0, else 0. Without COR, direct rebounds with
  // |v^l| (1 - 2 theta) and removes N^l (u^l - phi) = 2 theta (1 - theta) (v^l)^2 + |f| theta h
  // |v^l| by (4-6).
  double linear_fraction = 0;
  // The same along the free flight under f: s / h with s the first root of
  // (u^l - phi) + v^l s + f s^2 / 2 = 0; NaN when the particle starts below the floor (a scheme
  // that does not project) or does not move towards it.
  double flight_fraction = std::numeric_limits<double>::quiet_NaN();
  double speed_before = 0;  // |v^l|
  // Speeds at the floor before and after, from the discrete energy (4-5), which the schemes keep
  // exactly in free flight: V = sqrt(2 (E - E_floor)), E_floor = -f phi.
  double floor_speed_in = 0, floor_speed_out = 0;
  double energy_before = 0;  // E^l (4-5)
  double energy_after = 0;   // E at the end of the episode
  // The COR the scheme realised, -v_a / v_b in the paper's notation.
  double effective_cor() const { return floor_speed_out / floor_speed_in; }
};

// Finds the contact episodes of a run as it streams, step by step, in O(episodes) memory; episodes
// after the first `max_episodes` are counted as contact steps but not recorded.
class ContactDetector {
 public:
  ContactDetector(const Model& model, double h,
                  std::size_t max_episodes = std::numeric_limits<std::size_t>::max())
      : model_(model), h_(h), max_episodes_(max_episodes) {}

  // Step l from `before` (at t_l) to `after` (at t_{l+1}) with N^l = contact_force; returns whether
  // it is a contact step.
  bool add_step(std::int64_t l, const State& before, const State& after, double contact_force);

  const std::vector<ContactEpisode>& episodes() const { return episodes_; }
  // The last step added was a contact step (of a recorded episode or not).
  bool in_contact() const { return in_contact_; }

 private:
  double flight_fraction(const State& s) const;
  double floor_speed(const State& s) const;

  Model model_;
  double h_;
  std::size_t max_episodes_;
  std::vector<ContactEpisode> episodes_;
  bool in_contact_ = false, recording_ = false;
};

}  // namespace impact
