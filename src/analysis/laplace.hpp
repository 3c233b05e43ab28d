// The Laplace transform (2-5), (L w)(s) = int_0^inf w(t) e^{-st} dt, by GSL quadrature, for the
// numerical check of Lemma 1 (Section 3): an energy E(t) that is conserved has s (L E)(s) = E(0)
// for every s > 0, and by Lerch's theorem only then.
//
// Two kinds of w: a function known at every t >= 0 (the exact solution), integrated to infinity,
// and samples w_l = w(l h), l = 0..n, of a time-stepper, whose transform is that of an interpolant
// on [0, n h] plus a bound on the part beyond n h, where the samples say nothing.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/scene.hpp"

namespace impact {

struct LaplaceValue {
  double value = 0;       // the integral that was computed
  double abserr = 0;      // GSL's error estimates, summed over the pieces
  double tail_bound = 0;  // bound on |the part of the integral left out| (0 when none is)
};

// w smooth between the breakpoints (its jumps and kinks, in any order; those outside (0, inf)
// are ignored): QAG (GK21) on each piece between consecutive breakpoints, and QAGIU from the last
// one to infinity (analysis/quadrature.hpp). w is not evaluated where e^{-st}
// underflows to 0, so it may be undefined (or overflow) for huge t. Needs s > 0.
LaplaceValue laplace_transform(const std::function<double(double)>& w,
                               std::vector<double> breakpoints, double s);

// How the samples w_l = w(t_l) are continued between grid points.
enum class Interpolation {
  piecewise_constant,  // w(t) = w_{l+1} on (t_l, t_{l+1}], like the paper's v_h (Section 4)
  linear,              // the straight line through (t_l, w_l) and (t_{l+1}, w_{l+1})
};

// Transform of the interpolant of w_0..w_n (grid t_l = l h) on [0, t_stop], with QAG (GK15) on
// each step, where t_stop = n h, or the first grid time with s t >= 60
// (e^{-60} < 1e-26) if that comes first. tail_bound = sup |w| e^{-s t_stop} / s, where sup is the
// larger of `tail_sup` (a bound on |w(t)| for t > n h that the caller knows, e.g. E^0 from the
// energy inequality of Lemma 3) and the samples after t_stop. Needs s > 0, h > 0 and at least two
// samples.
LaplaceValue laplace_transform_samples(std::span<const double> samples, double h,
                                       Interpolation interpolation, double s, double tail_sup);

// A jump of a piecewise constant function: w(time+) - w(time-) = size.
struct Jump {
  double time = 0;
  double size = 0;
};

// The closed form against which the quadrature is checked: a w that is constant between jumps,
// w = w(0) + sum_{t_k < t} size_k, has s (L w)(s) - w(0) = sum_k size_k e^{-s t_k}. For the
// energy this is the signature of energy loss that Lemma 1 says is absent.
double laplace_jump_signature(std::span<const Jump> jumps, double s);

// Lemma 1 at one s: the signed relative deviation (s (L E)(s) - E(0)) / |E(0)| (0 when the lemma
// holds), the closed-form value of the same deviation from the jumps of E, and the error
// estimates of the quadrature, relative to |E(0)| as well.
struct Lemma1Point {
  double s = 0;
  double deviation = 0;
  double predicted = 0;
  double abserr = 0;
  double tail_bound = 0;
};

// The jumps of the exact energy (3-1): E is constant in flight and at rest, and impact k (speed
// V_k) changes it by -(1 - e^2) V_k^2 / 2 (e = COR; none when e = 1). Impacts up to `horizon`
// and at most `max_impacts` of them (a Zeno sequence has infinitely many, of geometrically
// vanishing size).
std::vector<Jump> exact_energy_jumps(const Model& model, const ExactSolution& exact, double horizon,
                                     std::int64_t max_impacts);

// Lemma 1 for the exact solution: E(t) = energy(model, exact.at(t)) transformed to infinity, with
// breakpoints at the impacts (at most 500) and the rest time.
Lemma1Point lemma1_exact(const Model& model, const State& initial, double s);

// Lemma 1 for a stepper's energies E^l = E(l h), l = 0..n: the transform of their interpolant
// (laplace_transform_samples, tail_sup bounding |E| after n h). `predicted` is the closed form of
// the piecewise constant interpolant continued by E^n: jumps E^{l+1} - E^l at t_l.
Lemma1Point lemma1_samples(std::span<const double> energies, double h, Interpolation interpolation,
                           double s, double tail_sup);

// The energies E^l = E(l h), l = 0..n, of a run of the scene's method.
std::vector<double> energy_samples(const Scene& scene);

}  // namespace impact
