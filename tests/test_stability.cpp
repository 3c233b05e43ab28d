// Numerical stability (experiments/stability): property tests on seeded random scenes across the
// extreme ranges (h from 1e-9 to 1, |v0| and |f| up to 1e8, f > 0, starting on the floor, COR
// 0..1, a floor at 1e6, eps from 1e-15 to 1e-2, c_N from 1e2 to 1e9; stability_properties.hpp),
// the safeguards' regression cases, the claims the experiment checks, and its key numbers against
// reference.toml.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "analysis/reference.hpp"
#include "analysis/stability/stability.hpp"
#include "analysis/stability/stability_cases.hpp"
#include "analysis/stability/stability_penalty.hpp"
#include "analysis/stability/stability_study.hpp"
#include "impact/forces/gsl_errors.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/fb_newton.hpp"
#include "stability_properties.hpp"

using namespace impact;
using namespace impact::stability;
using namespace impact::stability_properties;

TEST_CASE("C34: every method stays finite and feasible on 300 random extreme scenes",
          "[stability][property][claim]") {
  const RandomScene r = GENERATE(random_scenes(20130401, 300));
  for (const std::string method : {"direct", "fb_newton", "moreau_jean", "exact", "penalty"}) {
    if (method == "penalty" && r.cor) continue;  // penalty has no COR law (rejected)
    const Scene scene = r.scene(method);
    INFO(method << ": " << r);
    Properties p;
    if (method == "penalty") {
      // GSL may legitimately give up (a tolerance it cannot meet): then the run must stop with
      // NumericalError naming the step and the time, never with a NaN or a hang.
      try {
        p = run_properties(scene);
      } catch (const NumericalError& e) {
        CHECK_THAT(e.what(), Catch::Matchers::Contains("step ") &&
                                 Catch::Matchers::Contains("t = ") &&
                                 Catch::Matchers::Contains("GSL odeiv2 stepper"));
        continue;
      }
    } else {
      const bool fb = method == "fb_newton";
      REQUIRE_NOTHROW(p = run_properties(scene, 0.0, fb, r.epsilon));
    }
    CHECK(p.finite);
    const double f = std::fabs(r.f), h = r.h;
    if (method == "direct" || method == "fb_newton" || method == "exact") {
      // (2-2): u^l >= phi exactly (direct puts a contact step on phi; fb_newton's gap is
      // >= max(x_free, 0) >= 0; exact clamps the flight's gap at 0).
      CHECK(p.min_gap >= 0.0);
    } else if (method == "moreau_jean") {
      // Velocity-level contact, position not projected: it dips by at most a step's travel.
      CHECK(p.min_gap >= -(h * p.max_v + h * h * f) * (1 + 1e-12) - 4 * kEps * std::fabs(r.phi));
    } else {
      // Compliance: the energy v^2/2 - f (u - phi) + c_N pen^2/2 is conserved, so the deepest
      // penetration p solves c_N p^2/2 - |f| p = v0^2/2 + |f| (u0 - phi) (f <= 0; an upward
      // force only lowers it); 1e-6 relative for the integration, atol for the rest.
      const double c = r.stiffness, g0 = r.u0 - r.phi;
      const double depth = (f + std::sqrt(f * f + c * (r.v0 * r.v0 + 2 * f * g0))) / c;
      CHECK(-p.min_gap <= depth * (1 + 1e-6) + 1e-9 + 4 * kEps * std::fabs(r.phi));
    }
  }
}

TEST_CASE(
    "C33: Lemma 3's E^{l+1} <= E^l and N^l (u^{l+1} - phi) = 0 hold for direct and for fb_newton "
    "(up to eps/2 for the smoothed pair) on 300 random scenes",
    "[stability][property][claim]") {
  const RandomScene r = GENERATE(random_scenes(19680701, 300));
  // Lemma 3 is about the scheme without COR; with one, Section 5.2 says "energy is lost after
  // the particle's impact": true for f <= 0 (the next test shows f > 0), and for fb_newton only
  // up to |f| sqrt(eps/2): inside the smoothing layer (u - phi < sqrt(eps/2), where N > u - phi
  // still counts as contact) the COR law can act on a step that rises.
  if (r.cor && r.f > 0) return;
  for (const std::string method : {"direct", "fb_newton"}) {
    const Scene scene = r.scene(method);
    INFO(method << ": " << r);
    const bool fb = method == "fb_newton";
    const double layer = fb && r.cor ? std::fabs(r.f) * std::sqrt(r.epsilon / 2) : 0.0;
    Properties p;
    REQUIRE_NOTHROW(p = run_properties(scene, layer, fb, r.epsilon));
    CHECK(p.worst_energy_excess <= 0.0);
    // direct: N^l > 0 only on a step that ends on the floor, u^{l+1} = phi exactly.
    CHECK(p.worst_complementarity <= 0.0);
    if (!r.cor) {
      // (4-9) with the body force (a COR overwrites v, so the identity is for the scheme alone).
      const double T = scene.grid.t(scene.grid.steps);
      CHECK(p.impulse == Approx(p.last.v - r.v0 - r.f * T)
                             .epsilon(0)
                             .margin(impulse_identity_tolerance(scene, p)));
    }
  }
}

TEST_CASE(
    "stability: exact conserves the energy when COR = 1 and loses it monotonically when "
    "COR < 1, on 300 random scenes",
    "[stability][property][exact]") {
  const RandomScene r = GENERATE(random_scenes(5, 300));
  const Scene scene = r.scene("exact");
  INFO(r);
  AnyStepper stepper = make_stepper(scene);
  const Model& m = scene.model;
  const double E0 = energy(m, scene.initial);
  const bool elastic = !r.cor || *r.cor == 1.0;
  double max_u = std::fabs(r.u0), max_v = std::fabs(r.v0), worst_drift = 0, worst_rise = 0;
  State before = scene.initial;
  simulate(stepper, scene.initial, scene.grid,
           [&](std::int64_t l, const State& s, const StepInfo&) {
             max_u = std::fmax(max_u, std::fabs(s.u));
             max_v = std::fmax(max_v, std::fabs(s.v));
             // E from the closed form: one rounding of each term of v^2/2 - f u.
             const double tol = 8 * kEps * (max_v * max_v + std::fabs(m.f) * max_u);
             const double E = energy(m, s);
             if (elastic) worst_drift = std::fmax(worst_drift, std::fabs(E - E0) - tol);
             if (l > 0) worst_rise = std::fmax(worst_rise, E - energy(m, before) - 2 * tol);
             before = s;
           });
  CHECK(worst_drift <= 0.0);
  CHECK(worst_rise <= 0.0);
}

// ---- fb_newton's step solves (5-3): its N against GSL's Brent root of S in N ----

namespace {

struct SmoothedEquation {
  double d, h, eps;  // d = x_free - phi
};

// F_eps(a, b) = a + b - sqrt(a^2 + b^2 + eps) in the cancellation-free form of its positive part.
double fischer_burmeister(double a, double b, double eps) {
  const double r = std::sqrt(a * a + b * b + eps);
  return a + b > 0 ? (2 * a * b - eps) / (a + b + r) : a + b - r;
}

// S in the unknown that has no cancellation: in the gap a (b = 2 (a - d)/h^2 adds |d|) when
// d < 0, in the force b (a = d + b h^2 / 2 adds d) when d >= 0. Both increasing.
double residual_in_gap(double a, void* params) {
  const auto& e = *static_cast<const SmoothedEquation*>(params);
  return fischer_burmeister(a, 2 * (a - e.d) / (e.h * e.h), e.eps);
}
double residual_in_force(double b, void* params) {
  const auto& e = *static_cast<const SmoothedEquation*>(params);
  return fischer_burmeister(e.d + b * e.h * e.h / 2, b, e.eps);
}

// The velocity h N of the root, by Brent's method on a bracket of the root: by the quadratic
// a (a - d) = eps h^2 / 4 the root has a <= max(d, 0) + h sqrt(eps) / 2 and N <= sqrt(eps) / h.
double root_velocity(const SmoothedEquation& e) {
  const GslErrorsAsStatus statuses;  // the bracket test reports, GSL does not abort
  const bool in_gap = e.d < 0;
  double lo = 0, hi = in_gap ? e.h * std::sqrt(e.eps) : 2 * std::sqrt(e.eps) / e.h;
  gsl_function F{in_gap ? &residual_in_gap : &residual_in_force, const_cast<SmoothedEquation*>(&e)};
  std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &F, lo, hi);
  for (int i = 0; i < 500; ++i) {
    gsl_root_fsolver_iterate(solver.get());
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-14) == GSL_SUCCESS) break;
  }
  const double x = gsl_root_fsolver_root(solver.get());
  return in_gap ? 2 * (x - e.d) / e.h : e.h * x;
}

}  // namespace

TEST_CASE("stability: fb_newton's N is the root of (5-3), also where the smoothing dominates",
          "[stability][fb_newton]") {
  // Before the safeguard, Newton's relative stopping rule accepted N ~ sqrt(eps / 2e-15) when the
  // free flight ended within h sqrt(eps) of the floor, short of the root N ~ sqrt(eps)/h: 8.6% of
  // these steps were off by more than 0.1 sqrt(eps) in velocity, the worst by 0.99 sqrt(eps).
  std::mt19937_64 rng(17);
  auto unit = [&] { return std::uniform_real_distribution<double>(0.0, 1.0)(rng); };
  auto log_uniform = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit()); };
  double worst = 0;
  for (int i = 0; i < 3000; ++i) {
    const double h = log_uniform(-9, 0), eps = log_uniform(-15, -2);
    const double sign = unit() < 0.5 ? -1.0 : 1.0;
    const double d = unit() < 0.5 ? sign * h * log_uniform(-6, 4) * unit()
                                  : sign * log_uniform(-40, -3);  // near the floor
    FbNewtonParams params;
    params.epsilon = eps;
    FbNewton solver(Model{0.0, 0.0, {}}, h, params);
    State s{0.0, d / h};  // f = 0: x_free = h v0
    const SmoothedEquation e{h * s.v, h, eps};
    solver.initialize(s, 0);
    const StepInfo info = solver.do_step(s, 0);
    REQUIRE(info.converged);
    const double root = root_velocity(e);
    // Velocity h N against the root's, relative to the smoothing's own scale sqrt(eps) (what
    // fb_newton guarantees, fb_newton.cpp) plus the Brent interval (1e-14 relative).
    const double miss = std::fabs(h * info.contact_force - root);
    const double allowed = 0.1 * std::sqrt(eps) + 1e-12 * (std::fabs(s.v) + root);
    INFO("h = " << h << ", eps = " << eps << ", d = " << e.d << ": h N = " << h * info.contact_force
                << ", root " << root);
    CHECK(miss <= allowed);
    worst = std::fmax(worst, miss / std::sqrt(eps));
  }
  CHECK(worst <= 0.1);
}

// ---- The safeguards' regression cases ----

TEST_CASE("stability: a particle resting on a floor at 1e6 stays at rest at h = 1e-9",
          "[stability][fb_newton]") {
  // Before fb_newton worked in gap coordinates, u rounded to ulp(1e6) = 1.2e-10 fed back through
  // N = (2/h^2)(x - x_free): once the free flight dropped one ulp below the floor the step pushed
  // it back with a velocity 2 ulp/h = 0.23 m/s, an energy kick of 0.027 within T = 1e-4.
  const StabilityRun run = run_extreme_case("phi_1e6_rest", "fb_newton", -9);
  REQUIRE(run.T == 1e-4);
  CHECK(run.check.outcome == Outcome::ok);
  CHECK(run.check.error_u == 0.0);
  CHECK(run.check.max_energy_rise <= 0.0);  // measured 0 (E is -f phi to the last bit)
}

TEST_CASE("C31: Newton's last-ulp cycle ends at the bracket instead of max_iterations",
          "[stability][fb_newton][claim]") {
  // Found by fuzzing: with COR and eps = 1.8e-4 the particle rests in the smoothing layer, where
  // one ulp of x moves S by 1e-14 > the tolerance 1e-15. Newton then alternated between the two
  // doubles around the root and ran into max_iterations: "step 2221 (from t = 9.4849...): the
  // solve did not converge after 50 iterations".
  FbNewtonParams params;
  params.epsilon = 0.00018337695958614469;
  const Scene scene =
      make_scene(Model{0, -0.011918629996088805, 0.091513236556524727},
                 State{0, 1.2788217895354335}, 16.761957487131866, 0.0042705624171036601, params);
  AnyStepper stepper = make_stepper(scene);
  RunSummary summary;
  REQUIRE_NOTHROW(summary = simulate(stepper, scene.initial, scene.grid,
                                     [](std::int64_t, const State&, const StepInfo&) {}));
  CHECK(summary.max_iterations < 50);
}

TEST_CASE("stability: a failed step names the step, the time and the solver's reason",
          "[stability]") {
  using Catch::Matchers::Contains;
  auto failure = [](const Model& model, const State& initial, double T, double h,
                    const MethodParams& params) -> std::string {
    const Scene scene = make_scene(model, initial, T, h, params);
    AnyStepper stepper = make_stepper(scene);
    try {
      simulate(stepper, scene.initial, scene.grid,
               [](std::int64_t, const State&, const StepInfo&) {});
    } catch (const NumericalError& e) {
      CHECK_FALSE(e.converged);
      return e.what();
    }
    return "";
  };
  // Newton capped at 3 iterations on the step that lands on the floor.
  FbNewtonParams capped;
  capped.max_iterations = 3;
  CHECK_THAT(failure(Model{}, State{0.005, -1}, 0.01, 0.001, capped),
             Contains("step 4 ") && Contains("t = 0.004") &&
                 Contains("did not converge after 3 iterations") &&
                 Contains("Fischer-Burmeister") && Contains("max_iterations"));
  // GSL cannot meet a tolerance below rounding.
  PenaltyParams exacting;
  exacting.rtol = exacting.atol = 1e-300;
  CHECK_THAT(failure(Model{}, State{0.001, -1}, 1, 0.01, exacting),
             Contains("step 0 ") && Contains("t = 0") && Contains("rk8pd") &&
                 Contains("could not meet rtol = 1e-300"));
  // A contact of 1e-7 s resolved with h = 1: more than 1e6 ODE steps in one grid step. The guard
  // counts steps of any stepper; rk2's are the cheapest to count to 1e6 (0.08 s, rk8pd 0.5 s).
  PenaltyParams stiff;
  stiff.stiffness = 1e15;
  stiff.stepper = "rk2";
  CHECK_THAT(failure(Model{0, -9.8, {}}, State{0, 0}, 10, 1, stiff),
             Contains("step 0 ") && Contains("more than 1000000 ODE steps in this grid step") &&
                 Contains("c_N = 1e+15"));
}

// ---- Claims ----

TEST_CASE(
    "C32 (reproduced for COR = 0.75): with COR = 1 and f > 0 the discrete COR rule raises E on "
    "the contact step by f (u^l - phi), an artefact of the scheme",
    "[stability][claim][direct]") {
  // On the contact step the COR law sets v^{l+1} = -COR v^l at u^{l+1} = phi, so
  // E^{l+1} - E^l = -(1 - COR^2) (v^l)^2 / 2 + f (u^l - phi): with COR = 1 and an upward force the
  // particle gains f (u^l - phi) > 0. Case f_+9.8_cor1: u0 = 0.01, v0 = -1, f = 9.80665,
  // h = 1e-3: the step from u^l - phi = 4.9e-4 gains 9.80665 * 4.9033e-4 = 4.8085e-3.
  const StabilityRun run = run_extreme_case("f_+9.8_cor1", "direct", -3);
  CHECK(run.check.outcome == Outcome::energy_grows);
  CHECK(run.check.energy_rises == 1);
  CHECK(run.check.max_energy_rise == Approx(9.80665 * 4.9033250000000105e-4).epsilon(1e-12));
}

TEST_CASE(
    "C35: normal compliance tends to the Signorini impact as c_N grows (penetration V/sqrt(c_N) "
    "and duration pi/sqrt(c_N) and impulse 2V)",
    "[stability][claim][penalty]") {
  // Lemma 5's point of view: the compliance force of one contact tends to an impulse 2V delta
  // (COR = 1). With gravity the contact is an oscillation about g_eq = f/c_N entered at phase
  // alpha = atan2(V/w, -g_eq), w = sqrt(c_N): it lasts 2 (pi - alpha)/w and reaches
  // -g_eq + sqrt(g_eq^2 + V^2/c_N) below the floor; its impulse is 2V + |f| duration.
  const double V = std::sqrt(2 * 9.80665);
  for (double c_N : {1e4, 1e8, 1e12}) {
    const double w = std::sqrt(c_N), g_eq = kGravity / c_N;
    const double duration = 2 * (std::numbers::pi - std::atan2(V / w, -g_eq)) / w;
    const double depth = -g_eq + std::sqrt(g_eq * g_eq + V * V / c_N);
    const ContactResolution contact = resolve_contact("rk8pd", c_N);
    CAPTURE(c_N);
    REQUIRE(contact.outcome == Outcome::ok);
    // The grid samples the deepest point within (h w)^2 / 8 of depth (a cosine sampled at
    // spacing h = duration / 200), and the linear interpolation of the exit within (h w)^2 / 8
    // of a step.
    const double hw = duration / 200 * w;
    CHECK(contact.penetration == Approx(depth).epsilon(hw * hw / 8 + 1e-8));
    CHECK(contact.duration == Approx(duration).epsilon(hw * hw / 8 + 1e-8));
    CHECK(contact.impulse == Approx(2 * V - kGravity * contact.duration).epsilon(1e-8));
  }
}

// ---- The experiment's key numbers against reference.toml ----

TEST_CASE("stability: run_stability reproduces experiments/stability/reference.toml",
          "[stability][reference][regression]") {
  // Without the maps whose keys are totals over them (the 950 extreme-case runs, the 280 eps
  // runs, penalty over every c_N): the two runs the summary names and penalty at c_N = 1e6 and
  // 1e12, every stepper. What they give must equal the reference (1e-9 relative; they are the
  // same arithmetic as the driver's, so equal to the last bits on this machine).
  StabilityStudyOptions cheap;
  cheap.case_map = false;
  cheap.smoothing_map = false;
  cheap.stiffness_maps = false;
  const toml::table measured = run_stability(ExperimentContext{IMPACT_SOURCE_DIR, ""}, cheap);
  for (const char* key :
       {"fb_newton_phi_1e6_rest_h_1e-9.max_energy_rise", "direct_cor1_push_h_1e-3.max_energy_rise",
        "penalty.rk8pd.impulse_1e12", "penalty.bsimp.rest_ode_steps_1e6"})
    CHECK(measured.at_path(key).is_value());
  ReferenceRule rule;
  rule.measured_keys_only = true;
  const auto differences =
      compare_with_reference(measured, read_reference(IMPACT_SOURCE_DIR, "stability"), rule);
  for (const std::string& d : differences) FAIL_CHECK(d);
  CHECK(differences.empty());
}
