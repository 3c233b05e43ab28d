// The ensemble's per-step tally (ensemble.cpp): the summary's columns, loaded into and stored from
// vector lanes, and the steps of a block with the summary, the finite check alone, or neither.
// Included by ensemble.cpp alone, after its floating-point contraction setting, so that these
// inline functions are compiled as its vector kernels are.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <cstring>

#include "impact/ensemble/summary_lanes.hpp"

namespace impact::ensemble_tally {

// By reference, not by value: a vector returned from a function compiled without AVX would change
// the ABI (GCC's -Wpsabi).
template <class T, class Scalar>
[[gnu::always_inline]] inline void load(T& x, const Scalar* p) {
  std::memcpy(&x, p, sizeof x);
}

template <class T>
[[gnu::always_inline]] inline void store(double* p, const T& x) {
  std::memcpy(p, &x, sizeof x);
}

// The columns of the summary (Ensemble::keep_summary), each at its first particle.
struct SummaryColumns {
  const double* phi;
  double* u;  // u = phi + gap as the single-particle solvers return it (the initial u at first)
  double *steps, *episodes, *run, *max_u, *first_l, *first_u, *first_v, *poison;
};

// What the step loop keeps besides the state: nothing (the kernel alone), the finite check, or
// the finite check and the per-step summary.
enum class Tally { none, finite, full, full_started };

template <Tally T, class Real>
[[gnu::always_inline]] inline void load_summary(SummaryLanes<Real>& s, Real& phi, Real& u,
                                                Real& poison, const SummaryColumns& c,
                                                Eigen::Index i) {
  load(phi, c.phi + i);
  load(u, c.u + i);
  load(poison, c.poison + i);
  if constexpr (T != Tally::full && T != Tally::full_started) return;
  load(s.contacts.steps, c.steps + i);
  load(s.contacts.episodes, c.episodes + i);
  load(s.contacts.run, c.run + i);
  load(s.max_u, c.max_u + i);
  load(s.first_l, c.first_l + i);
  load(s.first_u, c.first_u + i);
  load(s.first_v, c.first_v + i);
}

template <Tally T, class Real>
[[gnu::always_inline]] inline void store_summary(const SummaryColumns& c, Eigen::Index i,
                                                 const SummaryLanes<Real>& s, const Real& u,
                                                 const Real& poison) {
  store(c.u + i, u);
  store(c.poison + i, poison);
  if constexpr (T != Tally::full && T != Tally::full_started) return;
  store(c.steps + i, s.contacts.steps);
  store(c.episodes + i, s.contacts.episodes);
  store(c.run + i, s.contacts.run);
  store(c.max_u + i, s.max_u);
  store(c.first_l + i, s.first_l);
  store(c.first_u + i, s.first_u);
  store(c.first_v + i, s.first_v);
}

// After a step from (u_before, v_before) at t_l, l in every lane: the summary, and the poison, the
// sum of every u^{l+1} + N^l, which is not finite for good once one of them was not (an overflow
// of finite values only makes a lane be re-run alone). A non-finite v makes u or N non-finite in
// the same step: in direct, v_free overflows only with the free flight u_free (which is u, or
// enters N), and v_contact is -COR v^l or v_free + h N; in moreau_jean, u is integrated from v.
template <Tally T, class Real>
[[gnu::always_inline]] inline void tally_step(SummaryLanes<Real>& s, Real& poison, const Real& l,
                                              const Real& phi, const Real& u_before,
                                              const Real& v_before, const Real& u,
                                              const Real& force) {
  if constexpr (T == Tally::full) summary_step(s, l, phi, u_before, v_before, u, force);
  if constexpr (T == Tally::full_started)
    summary_step<false>(s, l, phi, u_before, v_before, u, force);
  poison += u + force;
}

// Whether every lane's first contact episode has started: from then on the summary's capture of
// the first contact changes nothing, and the steps leave it out (Tally::full_started).
template <int Vectors, class Real>
[[gnu::always_inline]] inline bool all_started(const SummaryLanes<Real> (&summary)[Vectors]) {
  constexpr int kLanes = static_cast<int>(sizeof(Real) / sizeof(double));
  for (int b = 0; b < Vectors; ++b)
    for (int j = 0; j < kLanes; ++j)
      if (summary[b].contacts.episodes[j] == 0) return false;
  return true;
}

// Steps between two looks at all_started(): a look costs a few hundred cycles.
constexpr std::int64_t kStartedCheck = 256;

// The steps [k, steps) of a block with its tally: with Tally::full, the first contact is captured
// until all_started(), checked every kStartedCheck steps, and left out after.
template <Tally Summarize, int Vectors, class Real, class Step>
[[gnu::always_inline]] inline void tally_steps(std::int64_t steps, Real& l,
                                               SummaryLanes<Real> (&summary)[Vectors],
                                               const Step& step) {
  std::int64_t k = 0;
  if constexpr (Summarize == Tally::full)
    while (k < steps && !all_started(summary)) {
      const std::int64_t end = std::min(steps, k + kStartedCheck);
      for (; k < end; ++k, l += 1)
        for (int b = 0; b < Vectors; ++b) step.template operator()<Tally::full>(b, l);
    }
  constexpr Tally rest = Summarize == Tally::full ? Tally::full_started : Summarize;
  for (; k < steps; ++k, l += 1)
    for (int b = 0; b < Vectors; ++b) step.template operator()<rest>(b, l);
}

}  // namespace impact::ensemble_tally
