// The distance of two solution paths, sup_t |u(t) - w(t)|: two schemes on one grid (run in
// lockstep, without storing either path), or two exact solutions on [0, T]. Lemma 4 asks whether
// different solutions of (2-1)-(2-4) from the same (or nearby) data approach one another.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "impact/loop/simulate.hpp"
#include "impact/model/model.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"

namespace impact {

// One step of any method's stepper (a visit per step: for the second stepper of a lockstep run,
// so that the run is instantiated once per method, not once per pair of methods).
[[gnu::noinline]] StepInfo step_any(AnyStepper& stepper, State& s, std::int64_t l);

// Advances a second stepper in lockstep with the one simulate() drives, from the same initial
// state on the same grid, and records sup_l |u_a^l - u_b^l|.
template <Stepper A>
class LockstepStepper {
 public:
  LockstepStepper(A& a, AnyStepper& b, const State& initial, double h)
      : a_(a), b_(b), other_(initial), h_(h) {}

  void initialize(const State& s, std::int64_t l) {
    a_.initialize(s, l);
    std::visit(
        [&](auto& b) {
          if constexpr (!ParticleStepper<std::remove_cvref_t<decltype(b)>>)
            throw std::logic_error("LockstepStepper: a method with internal variables");
          else
            b.initialize(s, l);
        },
        b_);
    other_ = s;
  }

  StepInfo do_step(State& s, std::int64_t l) {
    const StepInfo info = a_.do_step(s, l);
    const StepInfo other_info = step_any(b_, other_, l);
    if (!(std::isfinite(other_.u) && std::isfinite(other_.v)) || !other_info.converged) [[unlikely]]
      throw_step_failure(l, static_cast<double>(l) * h_, other_, other_info);
    sup_distance_ = std::fmax(sup_distance_, std::fabs(s.u - other_.u));
    return info;
  }
  double sup_distance() const { return sup_distance_; }

 private:
  A& a_;
  AnyStepper& b_;
  State other_;
  double h_;
  double sup_distance_ = 0;
};

// sup over the scene's grid of |u_a - u_b|, u_a from the scene's method and u_b from `other` on
// the same data and grid.
double sup_distance(const Scene& scene, const MethodParams& other);

// sup over [0, T] of |u - w| for two exact solutions with the same f. Between the impact times
// of either, u - w is the difference of two parabolas with the same f, i.e. linear, so the sup
// is attained at 0, T or an impact time; a uniform sampling is added for the crowded impacts
// before a Zeno point that impact_times() leaves out.
double sup_distance(const ExactSolution& u, const ExactSolution& w, double T);

}  // namespace impact
