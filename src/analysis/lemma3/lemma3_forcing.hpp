// Lemma 3 (Section 4) with a time-dependent body force f(t) = f + a sin(omega t + phase): the
// paper says after the proof that "the estimates in Lemma 3 can be obtained even if the body
// force f is not a constant function". The printed bounds contain |f| and E^0 = (v^0)^2/2 - f u^0,
// which a non-constant f does not define, so each reading the text allows is measured. |f| is
// read as one number F over [0, T]:
//   sup       F = sup_[0,T] |f(t)|,
//   mean      F = (1/T) int_0^T |f| (the L1 norm over T),
//   rms       F = ((1/T) int_0^T f^2)^(1/2),
// with the force in E^0 either F with the sign of f(0) (so that a constant f gives the lemma as
// printed) or, in the readings *_f0, f(0) itself (the discrete energy (4-5) at t_0); or
//   constant  the constant part f alone, in |f| and in E^0 (the harmonic part ignored);
//   frozen    at each step l the force frozen at its value f(t_l), in |f| and in E^0.
// V(F, f_E) = sqrt((2 E^0 + 2 F |u^0| + F T)(1 + F T e^{F T})), E^0 = (v^0)^2/2 - f_E u^0 (read
// as in bounds.hpp, the exponent e^{|f|T} of (4-8)); 2 E^0 + 2 F |u^0| + F T is taken as 0 when a
// reading makes it negative (f_E u^0 > F |u^0| + F T/2: a *_f0 reading with f(0) > F).
//
// The proof's argument redone for f(t): with the step's mean force f^l (ForceFunction::step_mean),
// (4-1) and (4-2) give (v^{l+1})^2/2 - (v^l)^2/2 = (N^l + f^l)(u^{l+1} - u^l) and N^l (u^{l+1} -
// u^l) = -N^l (u^l - phi) <= 0 by (4-3), so |v^{l+1}| <= |v^l| + h |f^l| at every step (both signs
// of v^{l+1} + v^l): max|v^l| <= P = |v^0| + int_0^T |f|, without Gronwall and attained when f
// keeps the sign of v^0 and nothing is hit. With (4-2), |u^l| <= |u^0| + t_l max|v|: max|u^l| <=
// |u^0| + T P. And V >= P whenever F T >= int_0^T |f| and 2 E^0 + 2 F |u^0| >= (v^0)^2 (expand V^2
// - P^2 with x = F T: 2 |v^0| x <= x + (v^0)^2 x e^x), which sup, mean and rms with E^0 from +-F
// satisfy.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "analysis/energy_forcing.hpp"
#include "analysis/lemma3/bounds.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"

namespace impact::lemma3 {

enum class ForceReading { sup, mean, rms, sup_f0, mean_f0, rms_f0, constant, frozen };
inline constexpr std::array<ForceReading, 8> kForceReadings = {
    ForceReading::sup,     ForceReading::mean,   ForceReading::rms,      ForceReading::sup_f0,
    ForceReading::mean_f0, ForceReading::rms_f0, ForceReading::constant, ForceReading::frozen};
std::string_view reading_name(ForceReading reading);

// The norms of f over [0, T] that the readings use.
struct ForceNorms {
  double sup = 0;       // sup_[0,T] |f|, in closed form (endpoints and the crests inside)
  double integral = 0;  // int_0^T |f|, the step integrals of ForceFunction between the zeros of f
  double rms = 0;       // ((1/T) int_0^T f^2)^(1/2), GSL quadrature
};
ForceNorms force_norms(const Model& model, double T);

// One run's maxima against every reading (frozen: the worst step, max_l |v^l| / V(f(t_l)) and
// max_l |u^l| / (|u^0| + (T/2) V(f(t_l)))), and against the proof's bound P.
struct ForcingRatios {
  double velocity = 0;           // max|v^l| / V
  double displacement = 0;       // max|u^l| / (|u^0| + (T/2) V), as printed
  double displacement_full = 0;  // max|u^l| / (|u^0| + T V), the factor of (4-7) corrected
};

struct ForcingCase {
  double f = 0, amplitude = 0, omega = 0, phase = 0;  // the body force
  double u0 = 0, v0 = 0, h = 0;
  std::string_view method;  // "direct" or "fb_newton"
  Model model() const;      // phi = 0, no COR: (4-1)-(4-3) itself
};

struct ForcingRun {
  ForcingCase c;
  double T = 0, max_v = 0, max_u = 0;
  ForceNorms norms;
  std::array<ForcingRatios, kForceReadings.size()> readings;  // in the order of kForceReadings
  double proof_velocity = 0;                                  // max|v^l| / (|v^0| + int_0^T |f|)
  double proof_displacement = 0;  // max|u^l| / (|u^0| + T (|v^0| + int_0^T |f|))
  ForcedEnergyCounts energy;      // energy_forcing.hpp
};

// One run of the case's method over [0, kForcingT].
ForcingRun run_forcing_case(const ForcingCase& c);

inline constexpr double kForcingT = 2.0;
// The sweep: every combination, methods direct and fb_newton.
struct ForcingSweep {
  std::vector<double> f, amplitude, omega, phase, u0, v0, h;
};
// f in {-9.80665, -1, 0, 1}, amplitude in {0.1, 1, 5, 30}, omega in {1, 10, 100} rad/s, phase in
// {0, pi/2}, u0 in {0, 5} m, v0 in {-3, 2} m/s, h in {1e-2, 1e-3} s: 768 runs per method.
ForcingSweep full_forcing_sweep();
// The same with h = 1e-2 only, omega in {1, 100}: what the claim tests recompute.
ForcingSweep reduced_forcing_sweep();
std::vector<ForcingRun> run_forcing_sweep(const ForcingSweep& sweep);

// A bound holds when measured <= bound (1 + kForcingSlack): the slack covers the rounding of a
// maximum (a rebound 2 (phi - u^l)/h - v^l carries one ulp of u^l times 2/h, < 1e-11 relative
// here); a real failure is O(1) (the readings that fail, fail by more than 10%).
inline constexpr double kForcingSlack = 1e-9;

struct ForcingStats {
  int runs = 0, violations = 0;
  // Runs where the reading makes V = 0 < max|v^l| (2 E^0 + 2 F |u^0| + F T <= 0): violations whose
  // ratio is infinite, left out of `max` and counted here.
  int zero_bound = 0;
  double max = 0, median = 0;  // the largest finite ratio; the median of all
  ForcingCase worst;           // the first case (in sweep order) of `max`
};

struct ForcingSummary {
  int runs = 0;
  std::array<ForcingStats, kForceReadings.size()> velocity, displacement, displacement_full;
  ForcingStats proof_velocity, proof_displacement;
  ForcedEnergySummary energy;
};
// `method` empty: all runs; else those of that method.
ForcingSummary summarize_forcing(const std::vector<ForcingRun>& runs, std::string_view method);

}  // namespace impact::lemma3
