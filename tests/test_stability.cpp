// Numerical stability (experiments/stability): property tests on seeded random scenes
// across the extreme ranges (h from 1e-9 to 1, |v0| and |f| up to 1e8, f > 0, starting on the
// floor, COR 0..1, a floor at 1e6, eps from 1e-15 to 1e-2, c_N from 1e2 to 1e9), the safeguards'
// regression cases, the claims the experiment checks, and its key numbers against reference.toml.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <toml++/toml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "impact/fb_newton.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"
#include "impact/stability.hpp"

using namespace impact;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kGravity = -9.80665;

// ---- Random scenes over the extreme ranges ----

struct RandomScene {
  double phi = 0, u0 = 0, v0 = 0, f = 0;
  std::optional<double> cor;
  double h = 0;
  std::int64_t steps = 0;
  double epsilon = 1e-15;  // fb_newton
  double stiffness = 1e6;  // penalty

  std::string text(const std::string& method) const {
    std::string t = "[initial]\nu0 = " + impact::round_trip(u0) +
                    "\nv0 = " + impact::round_trip(v0) +
                    "\n[floor]\nphi = " + impact::round_trip(phi) + "\n";
    if (cor) t += "cor = " + impact::round_trip(*cor) + "\n";
    // T = steps h, and exactly `steps` steps (T/h rounds back to steps within 1e-9).
    t += "[force]\nf = " + impact::round_trip(f) +
         "\n[time]\nT = " + impact::round_trip(static_cast<double>(steps) * h) +
         "\nh = " + impact::round_trip(h) + "\n[method]\nname = \"" + method + "\"\n";
    if (method == "fb_newton") t += "epsilon = " + impact::round_trip(epsilon) + "\n";
    if (method == "penalty") t += "stiffness = " + impact::round_trip(stiffness) + "\n";
    return t;
  }
};

// A Catch2 generator of `count` scenes from a fixed seed (std::mt19937_64 and libstdc++'s
// distributions: the same scenes on every run).
class RandomScenes final : public Catch::Generators::IGenerator<RandomScene> {
 public:
  RandomScenes(std::uint64_t seed, int count) : rng_(seed), left_(count) { draw(); }
  const RandomScene& get() const override { return scene_; }
  bool next() override {
    if (--left_ <= 0) return false;
    draw();
    return true;
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
  double log_uniform(double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit()); }
  void draw() {
    RandomScene s;
    const double p = unit();
    s.phi = p < 0.3 ? 0.0 : p < 0.5 ? 1e6 : -1e3 + 2e3 * unit();
    s.u0 = s.phi + (unit() < 0.25 ? 0.0 : log_uniform(-12, 3));
    const double sign = unit() < 0.6 ? -1.0 : 1.0;
    s.v0 = unit() < 0.15 ? 0.0 : sign * log_uniform(-6, 8);
    const double q = unit();
    s.f = q < 0.15 ? 0.0 : q < 0.85 ? -log_uniform(-3, 8) : log_uniform(-3, 8);
    const double c = unit();
    if (c < 0.1)
      s.cor = 0.0;
    else if (c < 0.2)
      s.cor = 1.0;
    else if (c < 0.35)
      s.cor = unit();
    else if (c < 0.5)
      s.cor = 1 - 1e-3 * unit();
    s.h = log_uniform(-9, 0);
    s.steps = static_cast<std::int64_t>(log_uniform(0, 3.3));
    s.epsilon = log_uniform(-15, -2);
    s.stiffness = log_uniform(2, 9);
    scene_ = s;
  }
  std::mt19937_64 rng_;
  int left_;
  RandomScene scene_;
};

Catch::Generators::GeneratorWrapper<RandomScene> random_scenes(std::uint64_t seed, int count) {
  return Catch::Generators::GeneratorWrapper<RandomScene>(
      std::unique_ptr<Catch::Generators::IGenerator<RandomScene>>(new RandomScenes(seed, count)));
}

// What a run did, step by step, against the stability properties (experiments/stability/README.md).
struct Properties {
  bool finite = true;
  double min_gap = std::numeric_limits<double>::infinity();
  double max_v = 0, max_u = 0;
  double worst_energy_excess = -std::numeric_limits<double>::infinity();  // rise - allowance
  double worst_complementarity = 0;  // |N^l (u^{l+1} - phi)| beyond its allowance
  double impulse = 0;                // h sum N^l
  State last;
};

// The allowance on E^{l+1} - E^l beyond which a rise counts, on top of round-off (see
// check_stability: the free-flight terms, and 2/h times one ulp of u on a contact step).
double roundoff(const Model& model, double t, double h, const State& before, const State& after,
                double N, double max_u, double max_v) {
  const double f = std::fabs(model.f);
  const double ulp_u = kEps * std::fmax(std::fabs(before.u), std::fabs(model.phi));
  return 16 * kEps * (max_v * max_v + f * (max_u + t * max_v + t * t * f)) +
         (N > 0 ? 4 * std::fabs(after.v) * ulp_u / h : 0.0);
}

// extra_allowance: a further bound on E^{l+1} - E^l that the caller's theory gives.
Properties run_properties(const Scene& scene, double extra_allowance = 0, bool smoothed = false,
                          double eps = 0) {
  AnyStepper stepper = make_stepper(scene);
  const Model& m = scene.model;
  Properties p;
  State before = scene.initial;
  p.max_u = std::fabs(before.u);
  p.max_v = std::fabs(before.v);
  simulate(stepper, scene.initial, scene.grid,
           [&](std::int64_t l, const State& s, const StepInfo& info) {
             p.finite = p.finite && std::isfinite(s.u) && std::isfinite(s.v) &&
                        std::isfinite(info.contact_force);
             p.min_gap = std::fmin(p.min_gap, s.u - m.phi);
             p.last = s;
             if (l == 0) return;
             p.max_u = std::fmax(p.max_u, std::fabs(s.u));
             p.max_v = std::fmax(p.max_v, std::fabs(s.v));
             const double N = info.contact_force, gap = s.u - m.phi;
             p.impulse += scene.grid.h * N;
             double allowance =
                 roundoff(m, scene.grid.t(l), scene.grid.h, before, s, N, p.max_u, p.max_v) +
                 extra_allowance;
             if (smoothed) {
               // The root of (5-3) has a N = eps/2; Newton stops at a residual within
               // 1e-15 max(1, a, N) (a + N + sqrt(eps)) of it, or at the double nearest the
               // root, where N = (2/h^2)(a - a_free) is resolved to (2/h^2) ulp(a) (fb_newton.cpp,
               // check_stability).
               const double a = std::fabs(gap), h = scene.grid.h;
               const double residual =
                   1e-15 * std::fmax(1.0, std::fmax(a, N)) * (a + N + std::sqrt(eps)) +
                   2 * kEps * a * (2 * a / (h * h) + N);
               allowance += 0.5 * eps + residual;
               // (4-3) smoothed: 0 <= N^l (u^{l+1} - phi) = a N <= eps/2 + residual, with u
               // rounded to the floor's ulp.
               const double ulp_phi = 2 * kEps * std::fabs(m.phi);
               const double excess = std::fmax(N * gap - (0.5 * eps + residual + N * ulp_phi),
                                               -N * ulp_phi - N * gap);
               p.worst_complementarity = std::fmax(p.worst_complementarity, excess);
             } else {
               p.worst_complementarity = std::fmax(p.worst_complementarity, std::fabs(N * gap));
             }
             const double rise = energy(m, s) - energy(m, before);
             p.worst_energy_excess = std::fmax(p.worst_energy_excess, rise - allowance);
             before = s;
           });
  return p;
}

// h sum N^l = v^n - v^0 - f T (4-9) with the body force: each of the n steps adds round-off of
// order eps (max|v| + |f| T).
double impulse_identity_tolerance(const Scene& scene, const Properties& p) {
  const double T = scene.grid.t(scene.grid.steps);
  return 8 * kEps * static_cast<double>(scene.grid.steps + 1) *
         (p.max_v + std::fabs(scene.model.f) * T + 1e-300);
}

}  // namespace

TEST_CASE("stability: every method stays finite and feasible on 300 random extreme scenes",
          "[stability][properties]") {
  const RandomScene r = GENERATE(random_scenes(20130401, 300));
  for (const std::string method : {"direct", "fb_newton", "moreau_jean", "exact", "penalty"}) {
    if (method == "penalty" && r.cor) continue;  // penalty has no COR law (rejected)
    const Scene scene = parse_scene(r.text(method), "random");
    INFO(method << "\n" << r.text(method));
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
    "stability: Lemma 3, E^{l+1} <= E^l and N^l (u^{l+1} - phi) = 0, for direct and "
    "fb_newton (eps/2 for the smoothed pair) on 300 random scenes",
    "[stability][properties][claim]") {
  const RandomScene r = GENERATE(random_scenes(19680701, 300));
  // Lemma 3 is about the scheme without COR; with one, Section 5.2 says "energy is lost after
  // the particle's impact": true for f <= 0 (the next test shows f > 0), and for fb_newton only
  // up to |f| sqrt(eps/2): inside the smoothing layer (u - phi < sqrt(eps/2), where N > u - phi
  // still counts as contact) the COR law can act on a step that rises.
  if (r.cor && r.f > 0) return;
  for (const std::string method : {"direct", "fb_newton"}) {
    const Scene scene = parse_scene(r.text(method), "random");
    INFO(method << "\n" << r.text(method));
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
    "[stability][properties][exact]") {
  const RandomScene r = GENERATE(random_scenes(5, 300));
  const Scene scene = parse_scene(r.text("exact"), "random");
  INFO(r.text("exact"));
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
  gsl_set_error_handler_off();
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
    const StepInfo info = solver.step(s, 0);
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
  const Scene scene = parse_scene(
      "[initial]\nu0 = 1e6\nv0 = 0\n[floor]\nphi = 1e6\n[force]\nf = -9.80665\n"
      "[time]\nT = 1e-4\nh = 1e-9\n[method]\nname = \"fb_newton\"\n",
      "far_floor_rest");
  const StabilityCheck check = check_stability(scene);
  CHECK(check.outcome == Outcome::ok);
  CHECK(check.error_u == 0.0);
  CHECK(check.max_energy_rise <= 0.0);  // measured 0 (E is -f phi to the last bit)
}

TEST_CASE("stability: Newton's last-ulp cycle ends at the bracket instead of max_iterations",
          "[stability][fb_newton]") {
  // Found by fuzzing: with COR and eps = 1.8e-4 the particle rests in the smoothing layer, where
  // one ulp of x moves S by 1e-14 > the tolerance 1e-15. Newton then alternated between the two
  // doubles around the root and ran into max_iterations: "step 2221 (from t = 9.4849...): the
  // solve did not converge after 50 iterations".
  const Scene scene = parse_scene(
      "[initial]\nu0 = 0\nv0 = 1.2788217895354335\n[floor]\ncor = 0.091513236556524727\n"
      "[force]\nf = -0.011918629996088805\n[time]\nT = 16.761957487131866\n"
      "h = 0.0042705624171036601\n[method]\nname = \"fb_newton\"\n"
      "epsilon = 0.00018337695958614469\n",
      "two_cycle");
  AnyStepper stepper = make_stepper(scene);
  RunSummary summary;
  REQUIRE_NOTHROW(summary = simulate(stepper, scene.initial, scene.grid,
                                     [](std::int64_t, const State&, const StepInfo&) {}));
  CHECK(summary.max_iterations < 50);
}

TEST_CASE("stability: a failed step names the step, the time and the solver's reason",
          "[stability]") {
  using Catch::Matchers::Contains;
  auto failure = [](const std::string& text) -> std::string {
    const Scene scene = parse_scene(text, "failing");
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
  CHECK_THAT(failure("[initial]\nu0 = 0.005\nv0 = -1\n[time]\nT = 0.01\nh = 0.001\n"
                     "[method]\nname = \"fb_newton\"\nmax_iterations = 3\n"),
             Contains("step 4 ") && Contains("t = 0.004") &&
                 Contains("did not converge after 3 iterations") &&
                 Contains("Fischer-Burmeister") && Contains("max_iterations"));
  // GSL cannot meet a tolerance below rounding.
  CHECK_THAT(failure("[initial]\nu0 = 0.001\nv0 = -1\n[time]\nT = 1\nh = 0.01\n"
                     "[method]\nname = \"penalty\"\nrtol = 1e-300\natol = 1e-300\n"),
             Contains("step 0 ") && Contains("t = 0") && Contains("rk8pd") &&
                 Contains("could not meet rtol = 1e-300"));
  // A contact of 1e-7 s resolved with h = 1: more than 1e6 ODE steps in one grid step.
  CHECK_THAT(failure("[initial]\nu0 = 0\nv0 = 0\n[force]\nf = -9.8\n[time]\nT = 10\nh = 1\n"
                     "[method]\nname = \"penalty\"\nstiffness = 1e15\n"),
             Contains("step 0 ") && Contains("more than 1000000 ODE steps in this grid step") &&
                 Contains("c_N = 1e+15"));
}

// ---- Claims ----

TEST_CASE(
    "stability: the COR law raises the energy when f > 0 (Section 5.2's 'energy is lost' "
    "holds only for f <= 0)",
    "[stability][claim][direct]") {
  // On the contact step the COR law sets v^{l+1} = -COR v^l at u^{l+1} = phi, so
  // E^{l+1} - E^l = -(1 - COR^2) (v^l)^2 / 2 + f (u^l - phi): with COR = 1 and an upward force the
  // particle gains f (u^l - phi) > 0. u0 = 0.01, v0 = -1, f = 9.80665, h = 1e-3: the step from
  // u^l - phi = 4.9e-4 gains 9.80665 * 4.9033e-4 = 4.8085e-3.
  const Scene scene = parse_scene(
      "[initial]\nu0 = 0.01\nv0 = -1\n[floor]\ncor = 1\n[force]\nf = 9.80665\n"
      "[time]\nT = 1\nh = 0.001\n[method]\nname = \"direct\"\n",
      "push");
  const StabilityCheck check = check_stability(scene);
  CHECK(check.outcome == Outcome::energy_grows);
  CHECK(check.energy_rises == 1);
  CHECK(check.max_energy_rise == Approx(9.80665 * 4.9033250000000105e-4).epsilon(1e-12));
}

TEST_CASE(
    "stability: normal compliance tends to the Signorini impact as c_N grows (penetration "
    "V/sqrt(c_N), duration pi/sqrt(c_N), impulse 2V)",
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
    const double h = duration / 200;
    const Scene scene = parse_scene(
        "[initial]\nu0 = 0\nv0 = " + impact::round_trip(-V) +
            "\n[force]\nf = -9.80665\n[time]\nT = " + impact::round_trip(1.5 * duration) +
            "\nh = " + impact::round_trip(h) + "\n[method]\nname = \"penalty\"\n" +
            "stiffness = " + impact::round_trip(c_N) + "\n",
        "contact");
    AnyStepper stepper = make_stepper(scene);
    double min_u = 0, impulse = 0, exit = NAN;
    State before = scene.initial;
    simulate(stepper, scene.initial, scene.grid,
             [&](std::int64_t l, const State& s, const StepInfo& info) {
               if (l == 0) return;
               min_u = std::fmin(min_u, s.u);
               if (std::isnan(exit)) {
                 impulse += h * info.contact_force;
                 if (before.u < 0 && s.u >= 0)
                   exit = scene.grid.t(l - 1) + h * -before.u / (s.u - before.u);
               }
               before = s;
             });
    CAPTURE(c_N);
    // The grid samples the deepest point within (h w)^2 / 8 of depth (a cosine sampled at
    // spacing h), and the linear interpolation of the exit within (h w)^2 / 8 of a step.
    const double hw = h * w;
    CHECK(-min_u == Approx(depth).epsilon(hw * hw / 8 + 1e-8));
    CHECK(exit == Approx(duration).epsilon(hw * hw / 8 + 1e-8));
    CHECK(impulse == Approx(2 * V - kGravity * exit).epsilon(1e-8));
  }
}

// ---- The experiment's key numbers against reference.toml ----

TEST_CASE("stability: the library reproduces experiments/stability/reference.toml",
          "[stability][reference]") {
  const toml::table ref =
      toml::parse_file(std::string(IMPACT_SOURCE_DIR) + "/experiments/stability/reference.toml");
  auto number = [&](std::string_view table, std::string_view key) {
    const auto value = ref.at_path(std::string(table) + "." + std::string(key)).value<double>();
    REQUIRE(value);
    return *value;
  };
  {
    const Scene scene = parse_scene(
        "[initial]\nu0 = 0.01\nv0 = -1\n[floor]\nphi = 0\ncor = 1\n[force]\nf = 9.80665\n"
        "[time]\nT = 1\nh = 0.001\n[method]\nname = \"direct\"\n",
        "f_+9.8_cor1");
    const StabilityCheck check = check_stability(scene);
    // The same arithmetic as the driver: equal to the last bits.
    CHECK(check.max_energy_rise == number("direct_cor1_push_h_1e-3", "max_energy_rise"));
    CHECK(check.energy_rises == number("direct_cor1_push_h_1e-3", "energy_rises"));
  }
  {
    const Scene scene = parse_scene(
        "[initial]\nu0 = 1000000\nv0 = 0\n[floor]\nphi = 1000000\n[force]\nf = -9.80665\n"
        "[time]\nT = 0.0001\nh = 1e-9\n[method]\nname = \"fb_newton\"\n",
        "phi_1e6_rest");
    const StabilityCheck check = check_stability(scene);
    CHECK(check.max_energy_rise == number("fb_newton_phi_1e6_rest_h_1e-9", "max_energy_rise"));
    CHECK(check.error_u == number("fb_newton_phi_1e6_rest_h_1e-9", "error_u"));
    CHECK(check.max_iterations == number("fb_newton_phi_1e6_rest_h_1e-9", "max_iterations"));
  }
  // The outcome counts of exact over the 190 runs of the map: all ok.
  CHECK(number("outcomes.exact", "ok") == 190);
}
