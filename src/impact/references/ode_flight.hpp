// The flights of any body force f(t) (an expression above all) for the event-driven method
// event_driven: the free flight u'' = f(t), as y = (u - phi, v), y' = (v, f(t)), integrated by
// GSL odeiv2 rk8pd with tight tolerances, the impacts found by the certified search of
// flight_search.hpp inside each accepted ODE step, and the events of ExactMarch.
//
// Dense output: the state at a time t inside an accepted step [t_a, t_b] is one rk8pd step of
// length t - t_a from (t_a, y_a), no longer than the step the error control accepted, so it is as
// accurate as the step's end (an interpolant of the step ends would lose orders).
//
// The force bound over a step. An expression has no global bound, so each accepted step gets
//   M = max_i |f(s_i)| + max_i |f(s_(i+1)) - f(s_i)|
// from f at 9 evenly spaced points s_i of [t_a, t_b]: the sampled maximum plus the largest change
// between neighbours as a safety margin. For a force whose variation between neighbouring samples
// is at most that change (true for any f with |f''| (Delta/2)^2 / 2 below it, Delta the sample
// spacing), M bounds |f| on the step, and the search is then as certain as for a harmonic force:
// no contact, grazing or not, is missed. Not guaranteed: a spike of f narrower than the sample
// spacing, which rk8pd's own stages (13 per step) could miss as well; max_step caps the spacing.
//
// Lift-off: a resting particle lifts where f crosses 0 upward, found by sampling f every max_step/8
// and refining the first upward sign change with GSL's Brent. Between two samples where f <= 0 a
// positive excursion is looked for at a point sqrt(2) - 1 of the way in, and, where the three
// samples' maximum plus their largest change (the bound of an ODE step, above) does not exclude
// one, in both parts recursively (to 1e-9 of the spacing); before the root Brent found, 8 more
// samples so searched look for an earlier crossing. A table at 1 kHz, whose period is shorter
// than the spacing, lifts at each of its 1858 lift-offs in 2 s, as exact finds (it used to lift
// at 929: the scan stepped over every other one). A positive excursion narrower than the samples
// that fits between them unseen is not guaranteed to be found. A particle that leaves the floor
// with zero speed flies while g'' = f > 0: the first stretch is certified up to the last sample
// with f > 0, or, when f turns down before the first sample (f = 1e-300 - t), up to the zero of f
// (Brent). The chatter window of exact_march.hpp uses g_min and g_max from f sampled over the
// window, widened by the largest change between neighbouring samples (estimated, not certified,
// with no bound on f').
//
// A force of the state, f(t, u, v) (force.hpp): the flight is y' = (v, f(t, phi + y_0, y_1)), and
// the step's force bound samples f along the step's path (the dense output at the 7 inner
// samples): it bounds |g''| where the path goes, as above. On the floor the state is (phi, 0), so
// force(t), which the rest, the lift-off scan and the impulse of a rest read, is f(t, phi, 0): a
// resting particle lifts where that crosses 0 upward. An impact's `late` correction (Contact) and
// a zero-speed departure's first stretch also take f at (phi, 0), for the velocity of the contact
// (a change of O(late) in it, late below the root's bracket) and over the stretch's first sample
// (where the state is (phi, 0) to O(stretch^2)). A chatter window samples f at the corners of the
// box the bounces stay in, u in [phi, phi + V^2 / g], v in [-V, V], at each time: for a force
// affine in u and v these are its extremes over the box.
//
// Internal variables (model.hpp): the flight is y = (u - phi, v, z) with z' = g(t, u, v, z), the
// same rk8pd steps and dense output; z is continuous across an impact. From the time a contact is
// found the particle is on the floor, where f and the rates are read at (phi, 0, z(t)) with z(t)
// that of FloorInternal (internal_floor.hpp), until a flight starts again; internal_at(t) is the
// z of whichever holds at t. The chatter window's force samples take z on the floor too (not
// certified: z moves by at most W sup |g| inside the window, which its bound does not see).
//
// The bonding field (bonding.hpp): the pull -gamma beta^2 R(g) joins f in the flight, and the
// flight carries beta's variable (bond_fraction) and D (the energy spent on bonds) after the
// internal variables. The product form carries ln(beta/beta0): (ln beta)' = -(gamma R^2 - eps_a)_+
// keeps beta > 0 (and beta0 exactly while no bond breaks). The Frémond form carries beta itself,
// beta' = -(beta gamma R^2 - eps_a)_+ / b, read in [0, 1]. D' = -2 gamma beta beta' Phi(g). An
// accepted step's variable is clamped so that beta is at most its start's (and, Frémond, at least
// 0) and D to at least its start's, so that beta never rises and D never falls through the
// integrator's error (rk8pd's weights are not all positive). On the floor R(0) = 0: no pull, no
// damage, beta and D stay as they arrived. internal_at(t) gives beta, not the carried variable
// (z[kBondFraction], model.hpp).
//
// The end of the run. f is evaluated on [t0, end] only (OdeSettings::end; a force such as
// sqrt(2 - t) is defined up to T = 2 and no further): the ODE steps, the lift-off scan and the
// force's rate stop there, and a chatter window that reaches past it is not certified.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "impact/forces/force.hpp"
#include "impact/forces/internal.hpp"
#include "impact/model/model.hpp"
#include "impact/references/flight_search.hpp"
#include "impact/references/internal_floor.hpp"
#include "impact/references/rk8pd.hpp"

namespace impact {

struct OdeSettings {
  double rtol = 1e-12;
  double atol = 1e-14;
  double max_step = 0.01;
  double end = std::numeric_limits<double>::infinity();  // the last time f is evaluated at
};

// The flight's right-hand side (ode_flight.cpp), y = (u - phi, v, z, beta's variable, D):
// y' = (v, f(t, u, v, z) - gamma beta^2 R(u - phi), g(t, u, v, z), bond_rates) (bonding.hpp;
// the variable is ln(beta/beta0) in the product form, beta in the Frémond form).
struct FlightRhs {
  int operator()(double t, const double y[], double dydt[]) const;

  ForceFunction force;
  std::optional<InternalRates> rates;  // the internal variables' rates, if any
  std::optional<Bonding> bonds;        // a bonding field that acts
  std::size_t bond_at;                 // where beta's variable is in y
  double phi;
};

class OdeLaw {
 public:
  // Throws std::invalid_argument for an expression ForceFunction refuses.
  OdeLaw(const Model& model, const OdeSettings& settings);

  void start(double t, double gap, double v, bool at_crossing);
  std::optional<Contact> search(double horizon, long& budget);
  // The gap and velocity at t in the current ODE step (t >= its start).
  State at(double t) const;
  double certified() const { return certified_; }
  void give_up_until(double t) { certified_ = t; }
  double force_bound() const { return bound_; }
  // Why the ODE integration stopped (an rk8pd step that failed, the run's budget of ODE steps
  // used up), empty while it has not.
  std::string failure() const;
  // The ODE steps the run may take in all (event_driven sets it before each grid step).
  void set_ode_step_limit(long limit) { ode_step_limit_ = limit; }

  // f on the floor at rest, f(t, phi, 0) (and z on the floor): f(t) for a force of t alone.
  double force(double t) const {
    if (rate_count_ > 0) flight_.rhs().force.set_internal(floor_internal(t));
    return flight_.rhs().force.at(t, rest_);
  }
  // f at the gap and velocity y = (u - phi, v) and the internal variables z (the bonds' carried
  // variable, bond_fraction), the bonds' pull included: the particle's acceleration in flight.
  double force_on(double t, const State& y, const std::array<double, kMaxInternal>& z) const {
    if (rate_count_ > 0) flight_.rhs().force.set_internal(z);
    const double f = flight_.rhs().force.at(t, {phi_ + y.u, y.v});
    if (!bonds_) return f;
    return f - adhesive_pull(*bonds_, bond_fraction(*bonds_, z[rate_count_ + kBondFraction]), y.u);
  }
  // The internal variables the next start() begins the flight with (the run's initial values;
  // beta, not its logarithm).
  void set_internal(const std::array<double, kMaxInternal>& z);
  // z at t, in flight (t in the current ODE step) or on the floor (see above); beta for the bonds.
  std::array<double, kMaxInternal> internal_at(double t) const;
  double rate(double t) const;
  Lift lift_after(double t) const;
  double rest_impulse(double a, double b) const;
  std::optional<double> chatter_window(double t, double V, double e) const;

 private:
  void take_step();
  // The state and internal variables at t in the current ODE step.
  void dense(double t, State& y, std::array<double, kMaxInternal>& z) const;
  // z at t as the ODE carries it (the bonds' carried variable, bond_fraction).
  std::array<double, kMaxInternal> floor_internal(double t) const;
  // Keeps the bonds' beta from rising and D from falling over the current step (see above).
  void keep_bonds_monotone(std::array<double, kMaxInternal>& z) const;
  // A contact was found at t: the particle is on the floor from there (internal variables).
  void reach_floor(double t);
  std::optional<Contact> at_end();
  std::optional<detail::Bracket> hidden_rise(double a, double fa, double b, double fb,
                                             int depth) const;
  double first_upward(double a, double fa, double b, int depth) const;

  double phi_;
  State rest_;  // (phi, 0): the state of a particle at rest on the floor
  OdeSettings settings_;
  OdeSystem<FlightRhs> flight_;  // the integrator with the force and the rates it reads
  double t_a_ = 0, t_b_ = 0;
  State y_a_, y_b_;
  std::array<double, kMaxInternal> z_a_{}, z_b_{};  // the internal variables at t_a_ and t_b_
  std::size_t internal_count_ = 0;                  // the ODE's components after (u - phi, v)
  std::size_t rate_count_ = 0;                      // of which the model's internal variables
  std::optional<Bonding> bonds_;                // a bonding field that acts (bonded(), model.hpp)
  std::optional<FloorInternal> floor_;          // with internal variables
  bool on_floor_ = false;                       // z is floor_'s (or z_floor_) from floor_from_ on
  double floor_from_ = 0;                       // the time the particle reached the floor
  std::array<double, kMaxInternal> z_floor_{};  // z there (the bonds' stay so on the floor)
  double bound_ = 0, certified_ = 0, checked_ = 0;
  bool departing_ = false, at_crossing_ = false;
  long ode_steps_ = 0, ode_step_limit_ = std::numeric_limits<long>::max();
  bool ode_ok_ = true, out_of_steps_ = false;
  bool stiff_ = false;  // a search spent its budget on ODE steps, from stiff_from_ on
  double stiff_from_ = 0;
  int failed_status_ = 0;  // the GSL status of a step that failed
};

}  // namespace impact
