// The lower mass of the two-mass chain (chain.hpp) on the floor, for its event-driven reference
// (chain_reference.hpp): the rest, where it lifts off, how it leaves the floor with zero speed, and
// when an accumulation of impacts may be cut off. States are gaps (positions minus phi).
//
// At rest x1 = phi and x1' = 0, so the lower mass's equation gives the floor's push
//   N = -(m1 g + k d),  d = x2 - x1 - ell,
// (N >= 0 pushes up, (2-2)), and the upper mass is a harmonic oscillator under gravity and the
// spring, d'' = g - w2^2 d with w2^2 = k / m2, in closed form. The rest lasts while N >= 0 and
// ends at the first time N reaches 0 decreasing (N' = -k d' < 0: the upper mass pulls the lower one
// off). That time is found by search_contact (flight_search.hpp) run on N as on a gap: |N''| is at
// most k w2^2 times the amplitude of d about its equilibrium, so its steps cannot jump a root,
// and GSL's Brent refines the bracket where N decreases strictly.
//
// In flight the lower mass's gap obeys gap'' = g + (k / m1) d = -N / m1 with d'' = -w^2 d,
// w^2 = k (1/m1 + 1/m2): |gap'''| <= (k / m1) w A and |gap''''| <= (k / m1) w^2 A, A the stretch's
// amplitude hypot(d, d' / w), conserved in flight. These certify the first stretch of a flight
// that leaves the floor with zero speed, as zero_speed_departure() does for the particle:
// gap(s) >= a s^2 / 2 - C s^3 / 6 > 0 for s < 3 a / C when a = gap'' > 0, and
// gap(s) >= j s^3 / 6 - D s^4 / 24 > 0 for s < 4 j / D when a >= 0 < j = gap''' (a lift-off).
#pragma once

#include <cstdint>
#include <optional>

#include "impact/chain/chain.hpp"
#include "impact/references/flight_search.hpp"

namespace impact {

// d = x2 - x1 - ell of a state (gaps or positions alike).
inline double chain_stretch(const Chain& chain, const ChainState& s) {
  return s.q(1) - s.q(0) - chain.ell;
}

// N = -(m1 g + k d): the floor's push on the lower mass were it at rest in the state s.
inline double chain_rest_force(const Chain& chain, const ChainState& s) {
  return -(chain.m1 * chain.g + chain.k * chain_stretch(chain, s));
}

// The state tau >= 0 after a rest began in the state s0 (gaps, x1 = x1' = 0): the upper mass's
// oscillation in closed form.
ChainState chain_rest_at(const Chain& chain, const ChainState& s0, double tau);

// The first time in [t0, horizon] at which the contact force of a rest begun at t0 in the state s0
// reaches 0 decreasing (a Contact of flight_search.hpp on N: t is the first double with N <= 0),
// nullopt when there is none (or when the search's budget of steps, decreased, ran out).
std::optional<Contact> chain_lift(const Chain& chain, double t0, const ChainState& s0,
                                  double horizon, long& budget);

// For a lower mass on the floor with zero speed in the state s (gaps): the length of a certified
// first stretch of flight without contact (see above), half of the bound; 0 when neither bound
// gives one (N > 0, or N = 0 not decreasing: it stays), infinity when nothing brings it back.
double chain_departure(const Chain& chain, const ChainState& s);

// An accumulation of impacts (e < 1). For an impact of speed V whose state just after it (the
// lower mass launched at e V) is `after`: the window W within which all further impacts of the
// exact solution lie, the lower mass resting after them, if that can be certified; nullopt
// otherwise. The argument is the particle's (exact_march.hpp) with the push per unit mass
// p = -(g + (k / m1) d) in place of -f: over the trial window W0 = 4 e V / (p (1 - e)) (from p at
// the impact), |p'| = (k / m1) |d'| <= (k / m1) (w A + J), since each later impact changes the
// amplitude A of d by its velocity jump over w, and those jumps sum to at most
// J = (1 + e) V / (1 - rho_trial), rho_trial = (1 + e) / 2, when the impact speeds decay by a
// factor rho <= rho_trial. With p_min, p_max = p -+ (k / m1) (w A + J) W0: if p_min > 0,
// rho = e sqrt(p_max / p_min) <= rho_trial and W = 2 e V / (p_min (1 - rho)) <= W0, each flight
// after the impact lasts at most 2 w_j / p_min for its launch speed w_j, each impact speed is at
// most rho times the one before (consistent with the assumed decay), and all further impacts lie
// in [t, t + W].
std::optional<double> chain_chatter_window(const Chain& chain, double e, double V,
                                           const ChainState& after);

}  // namespace impact
