#include "analysis/stability/stability.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/steppers/fb_newton.hpp"

namespace impact::stability {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Thrown by the observer to stop a run that exceeds StabilityOptions::max_work.
struct WorkBudgetExceeded {};

// Watches a run step by step: min(u - phi), the error against `exact`, the iterations, and the
// steps where the energy (4-5) rose beyond what round-off (and fb_newton's smoothing) allows.
class StabilityObserver {
 public:
  StabilityObserver(const Scene& scene, const StabilityOptions& options, StabilityCheck& check)
      : model_(scene.model),
        grid_(scene.grid),
        exact_(scene.model, scene.initial),
        max_work_(options.max_work),
        also_(options.also),
        check_(check),
        previous_(scene.initial),
        max_u_(std::fabs(scene.initial.u)),
        max_v_(std::fabs(scene.initial.v)) {
    if (const auto* fb = std::get_if<FbNewtonParams>(&scene.method)) smoothing_ = *fb;
  }

  void operator()(std::int64_t l, const State& s, const StepInfo& info) {
    if (also_) also_(l, s, info);
    const double t = grid_.t(l);
    check_.min_gap = std::fmin(check_.min_gap, s.u - model_.phi);
    const State reference = exact_.at(t);
    check_.error_u = std::fmax(check_.error_u, std::fabs(s.u - reference.u));
    check_.amplitude = std::fmax(check_.amplitude, std::fabs(reference.u - model_.phi));
    if (l == 0) return;
    check_.steps = l;
    check_.work += info.iterations;
    check_.max_iterations = std::max(check_.max_iterations, info.iterations);
    if (max_work_ > 0 && check_.work > max_work_) throw WorkBudgetExceeded{};
    max_u_ = std::fmax(max_u_, std::fabs(s.u));
    max_v_ = std::fmax(max_v_, std::fabs(s.v));
    const double rise = energy(model_, s) - energy(model_, previous_);
    check_.max_energy_rise = l == 1 ? rise : std::fmax(check_.max_energy_rise, rise);
    if (rise > roundoff(t, s, info) + smoothing(s, info)) ++check_.energy_rises;
    previous_ = s;
  }

  // |E^n - E(t_n)| at the end of a finished run.
  double final_energy_error() const {
    return std::fabs(energy(model_, previous_) - energy(model_, exact_.at(grid_.t(grid_.steps))));
  }

 private:
  // Round-off of E^{l+1} - E^l (as in tests/test_schemes.cpp): that of evaluating E, whose free
  // flight from the last contact u_a + t (v_a + t f/2) has terms up to
  // max|u| + t max|v| + t^2 |f|, and on a contact step that of the rebound velocity, which
  // carries one ulp of u multiplied by 2/h.
  double roundoff(double t, const State& s, const StepInfo& info) const {
    const double f = std::fabs(model_.f);
    const double ulp_u = kEpsilon * std::fmax(std::fabs(previous_.u), std::fabs(model_.phi));
    return 16 * kEpsilon * (max_v_ * max_v_ + f * (max_u_ + t * max_v_ + t * t * f)) +
           (scheme_force(info) > 0 ? 4 * std::fabs(s.v) * ulp_u / grid_.h : 0.0);
  }

  // fb_newton's smoothed pair has a N = eps/2 at the root of (5-3), which (4-6) turns into
  // E^{l+1} - E^l = a N - N^l (u^l - phi) <= eps/2. Newton stops at a residual S with
  // |S| <= tolerance max(1, a, N), and 2 a N - eps = S (a + N + sqrt(a^2 + N^2 + eps)), so
  // a N <= eps/2 + tolerance max(1, a, N) (a + N + sqrt(eps)); or it stops at the double nearest
  // the root, where N = (2/h^2)(a - a_free) is resolved to (2/h^2) ulp(a): a N within
  // 2 eps_mach a (2 a / h^2 + N) of the root's.
  double smoothing(const State& s, const StepInfo& info) const {
    if (!smoothing_) return 0;
    const FbNewtonParams& fb = *smoothing_;
    const double a = std::fabs(s.u - model_.phi), N = scheme_force(info);
    return 0.5 * fb.epsilon +
           fb.tolerance * std::fmax(1.0, std::fmax(a, N)) * (a + N + std::sqrt(fb.epsilon)) +
           2 * kEpsilon * a * (2 * a / (grid_.h * grid_.h) + N);
  }

  const Model& model_;
  const Grid& grid_;
  const ExactSolution exact_;
  const std::int64_t max_work_;
  const std::function<void(std::int64_t, const State&, const StepInfo&)>& also_;
  std::optional<FbNewtonParams> smoothing_;
  StabilityCheck& check_;
  State previous_;
  double max_u_, max_v_;
};

// The outcome of a finished run: the energy first (where the theory bounds it), then the accuracy.
Outcome finished_outcome(const StabilityCheck& check, const Model& model) {
  if (check.energy_bound && check.energy_rises > 0) return Outcome::energy_grows;
  if (check.error_u >
      kAccuracy * check.amplitude + kAccuracyFloor * std::fmax(1.0, std::fabs(model.phi)))
    return Outcome::inaccurate;
  return Outcome::ok;
}

}  // namespace

std::string_view outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::ok:
      return "ok";
    case Outcome::inaccurate:
      return "inaccurate";
    case Outcome::energy_grows:
      return "energy_grows";
    case Outcome::failure:
      return "failure";
    case Outcome::non_finite:
      return "non_finite";
    case Outcome::over_budget:
      return "over_budget";
    case Outcome::rejected:
      return "rejected";
  }
  return "?";
}

StabilityCheck check_stability(const Scene& scene, const StabilityOptions& options) {
  StabilityCheck check;
  check.energy_bound = method_info(scene.method).can.energy_bound;
  std::optional<AnyStepper> stepper;
  try {
    stepper.emplace(make_stepper(scene));
  } catch (const std::invalid_argument& e) {  // e.g. a COR given to penalty
    check.outcome = Outcome::rejected;
    check.message = e.what();
    return check;
  }
  StabilityObserver observe(scene, options, check);
  try {
    simulate(*stepper, scene.initial, scene.grid, observe);
    check.error_energy = observe.final_energy_error();
  } catch (const NumericalError& e) {
    check.message = e.what();
    check.outcome = e.converged ? Outcome::non_finite : Outcome::failure;
  } catch (const WorkBudgetExceeded&) {
    check.message = "stopped after " + std::to_string(check.work) + " iterations in " +
                    std::to_string(check.steps) + " steps (budget " +
                    std::to_string(options.max_work) + ")";
    check.outcome = Outcome::over_budget;
  }
  check.mean_iterations =
      check.steps > 0 ? static_cast<double>(check.work) / static_cast<double>(check.steps) : 0.0;
  if (check.outcome == Outcome::ok) check.outcome = finished_outcome(check, scene.model);
  return check;
}

}  // namespace impact::stability
