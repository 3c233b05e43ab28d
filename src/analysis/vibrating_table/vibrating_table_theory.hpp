// The bouncing ball on a vibrating table y = a sin(omega t), in the table's frame u = x - y: the
// paper's model (2-1) with f(t) = -g + a omega^2 sin(omega t), phi = 0 and Newton's restitution e
// on the relative velocity. Everything here is dimensionless: the phase tau = omega t, speeds in
// units of g / omega, lengths of g / omega^2, so that u'' = -1 + Gamma sin(tau) with
// Gamma = a omega^2 / g. paper_notes/vibrating_table.md derives the closed forms below; the
// functions after them compute the same objects numerically from the exact impact map, to check
// the derivation.
#pragma once

#include <array>
#include <complex>
#include <optional>

namespace impact::vibrating_table {

// One impact: its phase tau in [0, 2 pi) and the relative take-off speed w = -e u'(tau-) >= 0.
struct TableImpact {
  double phase = 0.0;
  double speed = 0.0;
};

// The period-1 orbit with one impact every n table periods and its linearisation, in closed form.
struct PeriodOneOrbit {
  TableImpact impact;       // the fixed point: cos(phase) = Gamma_1 / Gamma, w = 2 pi n e / (1 + e)
  double impact_speed = 0;  // relative speed just before the impact, w / e = 2 pi n / (1 + e)
  // The Jacobian of the impact map d(phase', w') / d(phase, w) at the fixed point, row-major.
  std::array<double, 4> jacobian{};
  std::array<std::complex<double>, 2> eigenvalues{};
};

// tau reduced to [0, 2 pi): the phase of a time omega t + phase.
double wrap_phase(double tau);

// Gamma_1 = pi n (1 - e) / (1 + e): below it there is no period-1 orbit of period n.
double period_one_existence_threshold(double e, int n);
// Gamma_pd = sqrt(Gamma_1^2 + (2 (1 + e^2) / (1 + e)^2)^2): the stable period-1 orbit loses its
// stability there to a period-2 orbit (an eigenvalue crosses -1).
double period_doubling_threshold(double e, int n);
// The orbit at Gamma, e in (0, 1], n >= 1: the branch with sin(phase) >= 0 (stable between the two
// thresholds) or the other one (a saddle); nullopt below Gamma_1.
std::optional<PeriodOneOrbit> period_one_orbit(double gamma, double e, int n,
                                               bool stable_branch = true);

// The exact impact map: the next impact after `impact`, with the flight time, from the closed-form
// flight (ForceFunction::flight) and the first root of u(tau) > 0 bracketed with |u''| <= 1 + Gamma
// and refined by GSL's Brent solver. nullopt when the ball does not leave the table (w = 0: the
// sticking the map does not follow) or no impact is found within `max_flight` phase units.
struct MapStep {
  TableImpact next;
  double flight = 0.0;  // phase units from the impact to the next one
};
std::optional<MapStep> impact_map(const TableImpact& impact, double gamma, double e,
                                  double max_flight = 1e4);

// A fixed point of the n-th map (flight 2 pi n, same phase and speed) found by GSL's hybrid
// multidimensional root solver from `guess`; nullopt when it does not converge.
std::optional<TableImpact> map_fixed_point(const TableImpact& guess, double gamma, double e, int n);

// The Jacobian of impact_map at `impact` by central differences (row-major, as above); the phase
// of the image is unwrapped so that a flight of 2 pi n differentiates smoothly.
std::array<double, 4> map_jacobian(const TableImpact& impact, double gamma, double e);

// Eigenvalues of a row-major 2x2 matrix.
std::array<std::complex<double>, 2> eigenvalues_2x2(const std::array<double, 4>& m);

// Gamma where the numeric Jacobian at the numeric fixed point has an eigenvalue -1
// (1 + trace + det = 0), by Brent on Gamma between the first Gamma of the scan
// gamma_from, gamma_from + step, ... where it has changed sign and the one before.
double numeric_period_doubling_threshold(double e, int n, double gamma_from, double step);

}  // namespace impact::vibrating_table
