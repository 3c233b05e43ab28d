// The forced impact oscillator in closed form (paper_notes/impact_oscillator.md): the textbook
// x'' + x = cos(omega t), x <= sigma, x' -> -r x' at x = sigma (Shaw and Holmes 1983; Budd and
// Dux 1994), which is the package's u'' = -u - cos(omega t) + N, u >= phi, COR r with u = -x and
// phi = -sigma. Times are the same in both, so the impact phase (t mod 2 pi/omega) and the impact
// speed V (x' = V before, v = -V in the package) are too.
//
// Period-one (1, n) orbit: one impact per n forcing periods, T = 2 pi n/omega, at t0 with speed V.
// With gamma = 1/(1 - omega^2), c_s = (1 + r) sin T/(1 - cos T), r_- = (1 - r)/omega,
//   gamma cos(omega t0) = sigma + c_s V/2,   gamma sin(omega t0) = -r_- V/2,           (O-1)
//   V = [-2 c_s sigma + 2 sqrt(gamma^2 (c_s^2 + r_-^2) - sigma^2 r_-^2)]/(c_s^2 + r_-^2), (O-2)
// real iff |sigma| <= |gamma| sqrt(1 + (c_s/r_-)^2) (the saddle-node), the phase by atan2 of
// (O-1): cos(omega t0) alone, the form usually quoted, fixes omega t0 up to its sign only.
// The impact map (t_i, V_i) -> (t_(i+1), V_(i+1)) has at the orbit det J = r^2 and
//   Tr J = (1 + r^2) cos^2(T/2) + 2 r sin^2(T/2) - omega^2 (1 + r)^2 cos^2(T/2)
//          - omega^2 (1 + r) sigma sin T/V;                                              (O-3)
// the orbit period-doubles at Tr J = -(1 + r^2) and meets the saddle (the "-" root of (O-2)) at
// Tr J = 1 + r^2, the end of existence.
#pragma once

#include <array>
#include <optional>

#include "impact/model/model.hpp"
#include "impact/references/linear_flight.hpp"

namespace impact::impact_oscillator {

// The oscillator's data in the textbook's symbols.
struct Oscillator {
  double omega = 2.8;   // forcing frequency (the free one is 1)
  double r = 0.8;       // coefficient of restitution
  double sigma = -0.5;  // the wall x = sigma; the package's floor is phi = -sigma

  double phi() const { return -sigma; }
  double period() const;  // 2 pi/omega
  double gamma() const;   // 1/(1 - omega^2)
};

// u'' = -u - cos(omega t) as linear_flight.hpp's force: k = 1, a = -1, phase pi/2.
LinearForce oscillator_force(double omega);
// The package's model of the oscillator's floor and COR (the force is its expression or
// oscillator_force()).
Model oscillator_model(const Oscillator& o);
// "-u - cos(omega*t)" with omega written to round trip.
std::string oscillator_expression(double omega);

struct PeriodOneOrbit {
  double V = 0;      // impact speed
  double phase = 0;  // omega t0 in [0, 2 pi)
  double t0 = 0;     // impact time mod 2 pi/omega
  double T = 0;      // time between impacts, 2 pi n/omega
  double c_s = 0, r_minus = 0, gamma = 0;
  double acos_phase = 0;  // acos((sigma + c_s V/2)/gamma), the cos-only phase
};

// The orbit of (O-2) with the "+" root (branch = +1) or the "-" one (-1); nullopt where the roots
// are complex, V <= 0, or omega is 1 or a ratio n/m (gamma or c_s infinite). Admissibility (no
// contact between the impacts) is not checked here (orbit_is_admissible, oscillator_law.hpp).
std::optional<PeriodOneOrbit> period_one_orbit(const Oscillator& o, int n = 1, int branch = 1);

// (O-3) at an orbit of (O-2), and the Jacobian by the implicit function theorem.
double orbit_trace(const Oscillator& o, double V, int n = 1);
std::array<std::array<double, 2>, 2> orbit_jacobian(const Oscillator& o,
                                                    const PeriodOneOrbit& orbit);
// The multipliers' largest modulus, from Tr and det = r^2.
double leading_multiplier(double trace, double r);

// sigma where the "+" orbit ends (saddle-node, the existence bound) and where it period-doubles,
// for omega, r, n fixed: both in closed form (the PD one through m = sigma/V, below).
double saddle_node_sigma(double omega, double r, int n = 1);
double period_doubling_sigma(double omega, double r, int n = 1);
// |gamma|: the orbit's V reaches 0 (grazing), sigma_pd < sigma_g.
double grazing_sigma(double omega);
// omega where the orbit at (sigma, r, n) ends (saddle-node) and period-doubles, found by GSL's
// Brent in [lo, hi] (the first sign change on a scan of 400 points); nullopt without one.
std::optional<double> saddle_node_omega(double sigma, double r, double lo, double hi, int n = 1);
std::optional<double> period_doubling_omega(double sigma, double r, double lo, double hi,
                                            int n = 1);

// Grazing: a flight whose free motion would reach delta past the wall (its gap's minimum
// -delta, curvature a there) hits with speed sqrt(2 a delta) (1 + O(sqrt delta)) (Nordmark 1991);
// from the free periodic orbit u = |gamma| cos(omega t) (omega > 1) the first impact speed is
// exactly omega sqrt(delta (2 |gamma| - delta)), a = 1 + |gamma| = u'' at the minimum.
double grazing_curvature(double omega);
double grazing_first_speed(double omega, double delta);

// Chatter under a constant push a toward the wall: from a take-off speed v0 the impacts
// accumulate after 2 v0/(a (1 - r)); a push a0 + a1 (t - t0) adds the factor
// 1 - (2/3) a1 v0/(a0^2 (1 - r)) (to first order in v0).
double accumulation_time(double v0, double a, double r);
double accumulation_time_first_order(double v0, double a0, double a1, double r);
// At rest on the wall the push is phi + cos(omega t) (u convention): the particle can stick for
// omega t mod 2 pi in [-acos(-phi), acos(-phi)] (phi >= -1; every phase for phi >= 1) and lifts
// off at omega t = acos(-phi) + 2 pi m.
double lift_off_angle(double phi);

}  // namespace impact::impact_oscillator
