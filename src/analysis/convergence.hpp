// Section 4 measured: the existence proof passes to the limit h -> 0 in the scheme (4-1)-(4-3), and
// Lemma 4 claims the limit is unique. This file holds what the convergence and Lemma 4 experiments
// and their tests share:
//  - a stepper wrapper that tallies the discrete quantities of the proof along a run: the impulse
//    sum of (4-9), the complementarity sum of (4-10), the energy drop of (4-6), and each contact
//    episode with the effective coefficient of restitution the scheme realised;
//  - measure_convergence(): one run against the exact solution (measure_errors) plus those tallies;
//  - check_weak_solution(): whether an exact solution satisfies (2-1)-(2-4) in the weak sense the
//    proof's limit has (u >= phi, N >= 0 as a measure, int (u - phi) dN = 0, and
//    int u psi'' = int psi dN + f int psi for smooth test functions psi, by GSL quadrature);
//  - the two sides of (4-12) for a pair of exact solutions.
#pragma once

#include <toml++/toml.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/test_functions.hpp"
#include "impact/contact.hpp"
#include "impact/error_norms.hpp"
#include "impact/exact.hpp"
#include "impact/model.hpp"
#include "impact/run.hpp"

namespace impact {

// The discrete quantities of Section 4, summed over the steps l = 0..n-1 of a run.
struct ProofTallies {
  double impulse = 0;                    // h sum N^l: the left side of (4-9)
  double complementarity = 0;            // h sum N^l (u^{l+1} - phi): (4-10), 0 by (4-3)
  double energy_drop = 0;                // sum N^l (u^l - phi): E^0 - E^n by (4-6) (without COR)
  State last;                            // u^n, v^n: the state after the last step
  std::vector<ContactEpisode> episodes;  // the first kMaxEpisodes only (contact.hpp)
  static constexpr std::size_t kMaxEpisodes = 64;
};

// Wraps a stepper and tallies ProofTallies from what each step reports; it is itself a stepper,
// so measure_errors() can run it and the errors and the tallies come from one and the same run.
template <class Stepper>
class TallyingStepper {
 public:
  TallyingStepper(Stepper& inner, const Model& model, double h, ProofTallies& tallies)
      : inner_(inner), model_(model), h_(h), tallies_(tallies) {}

  void initialize(const State& s, std::int64_t l) {
    inner_.initialize(s, l);
    contacts_ = ContactDetector(model_, h_, ProofTallies::kMaxEpisodes);
  }

  StepInfo do_step(State& s, std::int64_t l) {
    const State before = s;
    const StepInfo info = inner_.do_step(s, l);
    const double N = info.contact_force, phi = model_.phi;
    tallies_.impulse += h_ * N;
    tallies_.complementarity += h_ * N * (s.u - phi);
    tallies_.energy_drop += N * (before.u - phi);
    if (contacts_.add_step(l, before, s, N)) {  // mirror the detector's episodes in the tallies
      const std::vector<ContactEpisode>& found = contacts_.episodes();
      if (found.size() > tallies_.episodes.size())
        tallies_.episodes.push_back(found.back());
      else if (!found.empty())
        tallies_.episodes.back() = found.back();
    }
    tallies_.last = s;
    return info;
  }

 private:
  Stepper& inner_;
  Model model_;
  double h_;
  ProofTallies& tallies_;
  ContactDetector contacts_{model_, h_, ProofTallies::kMaxEpisodes};
};

// One run of a method on [0, T] with step h against the exact solution.
struct ConvergencePoint {
  double h = 0;
  double t_end = 0;  // n h, the last grid time (>= T)
  State initial, final;
  double f = 0;
  ErrorNorms errors;
  ProofTallies tallies;
  // (4-9) as printed: h sum N^l - (v^n - v^0); omits the body force.
  double impulse_residual_printed() const { return tallies.impulse - (final.v - initial.v); }
  // (4-9) with the body force: h sum N^l - (v^n - v^0 - f t_n).
  double impulse_residual_corrected() const {
    return tallies.impulse - (final.v - initial.v - f * t_end);
  }
  // E^0 - E^n, to compare with the energy drop sum N^l (u^l - phi) of (4-6).
  double energy_loss(const Model& model) const {
    return energy(model, initial) - energy(model, final);
  }
};

// Runs `method` (a name of the registry: "direct", "moreau_jean", ...) on the scene given by the
// data, with the scene's grid rule (n = T/h rounded when within 1e-9, else ceil(T/h)), and
// measures its errors against the exact solution of `reference` (the scheme's own model when
// absent; another one to ask which solution of (2-1)-(2-4) a sequence of runs approaches).
ConvergencePoint measure_convergence(std::string_view method, const Model& model,
                                     const State& initial, double T, double h,
                                     const std::optional<Model>& reference = std::nullopt);

// Advances a second stepper in lockstep with the one simulate() drives, from the same initial
// state on the same grid, and records sup_l |u_a^l - u_b^l|: the distance of two solution paths
// without storing either.
template <class A, class B>
class LockstepStepper {
 public:
  LockstepStepper(A& a, B& b, const State& initial, double h)
      : a_(a), b_(b), other_(initial), h_(h) {}

  void initialize(const State& s, std::int64_t l) {
    a_.initialize(s, l);
    b_.initialize(s, l);
    other_ = s;
  }

  StepInfo do_step(State& s, std::int64_t l) {
    const StepInfo info = a_.do_step(s, l);
    const StepInfo other_info = b_.do_step(other_, l);
    if (!(std::isfinite(other_.u) && std::isfinite(other_.v)) || !other_info.converged) [[unlikely]]
      throw_step_failure(l, static_cast<double>(l) * h_, other_, other_info);
    sup_distance_ = std::fmax(sup_distance_, std::fabs(s.u - other_.u));
    return info;
  }
  double sup_distance() const { return sup_distance_; }

 private:
  A& a_;
  B& b_;
  State other_;
  double h_;
  double sup_distance_ = 0;
};

// sup over the grid of |u_a - u_b| for two methods run on the same data and grid.
double sup_distance(std::string_view method_a, std::string_view method_b, const Model& model,
                    const State& initial, double T, double h);

// sup over [0, T] of |u - w| for two exact solutions with the same f. Between the impact times
// of either, u - w is the difference of two parabolas with the same f, i.e. linear, so the sup
// is attained at 0, T or an impact time; a uniform sampling is added for the crowded impacts
// before a Zeno point that impact_times() leaves out.
double sup_distance(const ExactSolution& u, const ExactSolution& w, double T);

// The step h = t_impact / (m + theta): the grid point t_m lies a fraction theta of a step before
// the impact at t_impact (for f = 0 the particle is then theta h |v| above the floor at t_m).
inline double step_with_fraction(double t_impact, std::int64_t m, double theta) {
  return t_impact / (static_cast<double>(m) + theta);
}

// The weak formulation of (2-1)-(2-4) that the limit of Section 4 satisfies, checked on an exact
// solution over [0, T].
struct WeakSolutionCheck {
  double min_gap = 0;           // min of u - phi over a fine sampling and the impact times
  double min_cell_impulse = 0;  // min over a partition of the impulse of a cell: N >= 0
  double total_impulse = 0;     // N([0, T]) = impulse(0, T)
  double complementarity = 0;   // int_(0,T] (u - phi) dN, by Stieltjes integration by parts
  double max_weak_residual =
      0;                      // max over test functions of |int u psi'' - int psi dN - f int psi|
  double max_weak_scale = 0;  // max over test functions of |int u psi''|, the residual's scale
  int test_functions = 0;
};
WeakSolutionCheck check_weak_solution(const ExactSolution& x, const Model& model, double T);

// The terms of (4-12) at time t for two solutions u, w of (2-1) with the same constant f.
struct EnergyIdentity412 {
  double lhs = 0;           // (1/2) int_0^t d/dtau z_tau^2 = (z_t^2(t) - z_t^2(0)) / 2
  double paper_rhs = 0;     // -u_t(t) w_t(t) + u_t(0) w_t(0), (4-12)'s last line
  double force_terms = 0;   // f (u(t) - u(0) + w(t) - w(0)), dropped by (4-12) when f != 0
  double dropped_n1_u = 0;  // int_0^t N1 u_tau = E_u(t) - E_u(0), set to 0 by the proof
  double dropped_n2_w = 0;  // int_0^t N2 w_tau = E_w(t) - E_w(0), set to 0 by the proof
  double paper_413 = 0;     // z_t^2(t) - z_t^2(0), which (4-13) claims is 0
  // lhs = paper_rhs + force_terms + dropped_n1_u + dropped_n2_w holds for every pair.
};
EnergyIdentity412 energy_identity_412(const ExactSolution& u, const ExactSolution& w,
                                      const Model& model, double t);

// The summary.toml form of a fitted order.
toml::table order_fit_table(const OrderFit& fit);

}  // namespace impact
