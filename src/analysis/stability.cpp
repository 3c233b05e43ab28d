#include "analysis/stability.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "impact/exact.hpp"
#include "impact/fb_newton.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"

namespace impact {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Thrown by the observer to stop a run that exceeds StabilityOptions::max_work.
struct WorkBudgetExceeded {};

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
  const Model& model = scene.model;
  const Grid& grid = scene.grid;
  const ExactSolution exact(model, scene.initial);
  StabilityCheck check;
  const std::string_view method = method_name(scene.method);
  const bool scheme = method == "direct" || method == "fb_newton";
  check.energy_bound = scheme || method == "exact";
  // fb_newton's smoothed pair has a N = eps/2 at the root of (5-3), which (4-6) turns into
  // E^{l+1} - E^l = a N - N^l (u^l - phi) <= eps/2. Newton stops at a residual S with
  // |S| <= tolerance max(1, a, N), and 2 a N - eps = S (a + N + sqrt(a^2 + N^2 + eps)), so
  // a N <= eps/2 + tolerance max(1, a, N) (a + N + sqrt(eps)); or it stops at the double nearest
  // the root, where N = (2/h^2)(a - a_free) is resolved to (2/h^2) ulp(a): a N within
  // 2 eps_mach a (2 a / h^2 + N) of the root's.
  const auto* fb_params = std::get_if<FbNewtonParams>(&scene.method);
  const bool smoothed = fb_params != nullptr;
  const FbNewtonParams fb = smoothed ? *fb_params : FbNewtonParams{};
  const double f = std::fabs(model.f);

  AnyStepper stepper = make_stepper(scene);
  State previous = scene.initial;
  double max_u = std::fabs(previous.u), max_v = std::fabs(previous.v);
  auto observe = [&](std::int64_t l, const State& s, const StepInfo& info) {
    const double t = grid.t(l);
    check.min_gap = std::fmin(check.min_gap, s.u - model.phi);
    const State reference = exact.at(t);
    check.error_u = std::fmax(check.error_u, std::fabs(s.u - reference.u));
    check.amplitude = std::fmax(check.amplitude, std::fabs(reference.u - model.phi));
    if (l == 0) return;
    check.steps = l;
    check.work += info.iterations;
    check.max_iterations = std::max(check.max_iterations, info.iterations);
    if (options.max_work > 0 && check.work > options.max_work) throw WorkBudgetExceeded{};
    max_u = std::fmax(max_u, std::fabs(s.u));
    max_v = std::fmax(max_v, std::fabs(s.v));
    // Round-off of E^{l+1} - E^l (as in tests/test_schemes.cpp): that of evaluating E, whose
    // free flight from the last contact u_a + t (v_a + t f/2) has terms up to
    // max|u| + t max|v| + t^2 |f|, and on a contact step that of the rebound velocity, which
    // carries one ulp of u multiplied by 2/h.
    const double rise = energy(model, s) - energy(model, previous);
    const double ulp_u = kEpsilon * std::fmax(std::fabs(previous.u), std::fabs(model.phi));
    const double roundoff = 16 * kEpsilon * (max_v * max_v + f * (max_u + t * max_v + t * t * f)) +
                            (info.contact_force > 0 ? 4 * std::fabs(s.v) * ulp_u / grid.h : 0.0);
    check.max_energy_rise = l == 1 ? rise : std::fmax(check.max_energy_rise, rise);
    double smoothing = 0;
    if (smoothed) {
      const double a = std::fabs(s.u - model.phi), N = info.contact_force;
      smoothing = 0.5 * fb.epsilon +
                  fb.tolerance * std::fmax(1.0, std::fmax(a, N)) * (a + N + std::sqrt(fb.epsilon)) +
                  2 * kEpsilon * a * (2 * a / (grid.h * grid.h) + N);
    }
    if (rise > roundoff + smoothing) ++check.energy_rises;
    previous = s;
  };
  try {
    simulate(stepper, scene.initial, grid, observe);
    check.error_energy =
        std::fabs(energy(model, previous) - energy(model, exact.at(grid.t(grid.steps))));
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
  if (check.outcome != Outcome::ok) return check;
  if (check.energy_bound && check.energy_rises > 0) {
    check.outcome = Outcome::energy_grows;
  } else if (check.error_u >
             kAccuracy * check.amplitude + kAccuracyFloor * std::fmax(1.0, std::fabs(model.phi))) {
    check.outcome = Outcome::inaccurate;
  }
  return check;
}

}  // namespace impact
