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
//
// Rest: the particle rests from t_{l+1} when the run ends in an episode that starts with step l and
// lasts at least kMinRestSteps steps (Figure 4; experiments/figure4/README.md, "Rest time").
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "impact/model/model.hpp"

namespace impact {

// The contact-step rule for one particle (Real = double, Mask = bool) or a vector of particles (the
// ensemble, ensemble.hpp; Mask its comparison result). Written through `contact` because a function
// returning a vector type would change the ABI between instruction sets.
template <class Real, class Mask>
void is_contact_step(const Real& phi, const Real& u_after, const Real& contact_force,
                     Mask& contact) {
  contact = contact_force > u_after - phi;
}

inline bool is_contact_step(const Model& model, const State& after, double contact_force) {
  bool contact;
  is_contact_step(model.phi, after.u, contact_force, contact);
  return contact;
}

// What a run needs to know about its contact steps in O(1) memory: how many, how many episodes,
// and how long the episode it is in has lasted. Counts are held in Real (a double, or a vector of
// doubles in the ensemble), exact since a run has at most 2^53 steps (Grid).
template <class Real>
struct ContactCount {
  Real steps{};     // contact steps so far
  Real episodes{};  // contact episodes so far
  Real run{};       // length of the episode the last step belongs to; 0 after a free step
};

// Adds a step; `contact` is is_contact_step()'s result for it. Each selection is on one
// comparison, so that a vector of particles takes the same operations as one particle (combined
// masks made GCC build AVX-512 masks lane by lane, ensemble.cpp).
template <class Real, class Mask>
void count_contact(ContactCount<Real>& c, const Mask& contact) {
  c.steps = contact ? c.steps + 1 : c.steps;
  c.run = contact ? c.run + 1 : Real{};
  c.episodes = c.run == 1 ? c.episodes + 1 : c.episodes;
}

// Shortest final episode that counts as rest: an impact of `direct` lasts one step, or two when
// theta > 1/2; with a COR every scheme impact lasts one step.
constexpr std::int64_t kMinRestSteps = 3;

// For the count of a whole run on `grid`: t_{l+1} for the first step l of the final episode when
// the run ends in one of at least kMinRestSteps steps (l = steps - run), the first grid time from
// which the particle never leaves the floor; nullopt when it is still bouncing at the end.
inline std::optional<double> rest_time(const ContactCount<double>& c, const Grid& grid) {
  if (c.run < static_cast<double>(kMinRestSteps)) return std::nullopt;
  return grid.t(grid.steps - static_cast<std::int64_t>(c.run) + 1);
}

// Episodes before rest (all of them when the particle does not rest).
inline std::int64_t impacts(const ContactCount<double>& c) {
  return static_cast<std::int64_t>(c.episodes) - (c.run >= static_cast<double>(kMinRestSteps));
}

// The fraction of step l flown before the floor along the straight line from `before` (the state
// at t_l), as a time: (u^l - phi) / |v^l| for v^l < 0 (0 for a particle already below the floor),
// else 0. t_l plus this is where a scheme's first contact is placed (error_norms.hpp, summary.hpp).
inline double floor_crossing(const Model& model, const State& before) {
  return before.v < 0 ? std::fmax(0.0, (before.u - model.phi) / -before.v) : 0.0;
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
// after the first `max_episodes` are counted (count()) but not recorded, so max_episodes = 0 counts
// in O(1) memory without allocating.
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
  bool in_contact() const { return count_.run > 0; }
  // All contact steps and episodes, recorded or not.
  const ContactCount<double>& count() const { return count_; }

 private:
  double flight_fraction(const State& s) const;
  double floor_speed(const State& s) const;

  Model model_;
  double h_;
  std::size_t max_episodes_;
  std::vector<ContactEpisode> episodes_;
  ContactCount<double> count_;
  bool recording_ = false;
};

}  // namespace impact
