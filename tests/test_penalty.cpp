// Normal compliance (Section 5), N = c_N max(phi - u, 0), against its closed forms: with f = 0 a
// contact is half a period of the oscillator u'' = -c_N (u - phi), so it lasts pi/sqrt(c_N),
// penetrates |v|/sqrt(c_N) and gives back the velocity it took (the energy v^2/2 + c_N pen^2/2 is
// conserved).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <variant>

#include "impact/run/any_stepper.hpp"
#include "impact/steppers/penalty.hpp"
#include "scene/read_scene.hpp"

namespace {

using impact::Model;
using impact::Penalty;
using impact::PenaltyParams;
using impact::State;
using impact::StepInfo;

constexpr double kPi = std::numbers::pi;

struct Run {
  State s;
  bool converged = true;
  double min_N = std::numeric_limits<double>::infinity();
  double min_u = std::numeric_limits<double>::infinity();
  double impulse = 0;          // h sum N^l
  long contact_ode_steps = 0;  // ODE steps of the grid steps with N^l > 0
  double max_energy_drift = 0;
};

// Steps l = from .. to-1, initializing the stepper at (t_from, s) first unless it continues its
// own integration; the energy drift is that of v^2/2 - f u + c_N max(phi - u, 0)^2 / 2.
Run run(Penalty& pen, const Model& model, double c_N, State s, double h, std::int64_t from,
        std::int64_t to, bool continues = false) {
  if (!continues) pen.initialize(s, from);
  auto energy = [&](const State& x) {
    const double pen_depth = std::fmax(model.phi - x.u, 0.0);
    return 0.5 * x.v * x.v - model.f * x.u + 0.5 * c_N * pen_depth * pen_depth;
  };
  Run r;
  const double E0 = energy(s);
  for (std::int64_t l = from; l < to; ++l) {
    const StepInfo info = pen.do_step(s, l);
    r.converged = r.converged && info.converged;
    r.min_N = std::fmin(r.min_N, info.contact_force);
    r.min_u = std::fmin(r.min_u, s.u);
    r.impulse += h * info.contact_force;
    if (info.contact_force > 0) r.contact_ode_steps += info.iterations;
    r.max_energy_drift = std::fmax(r.max_energy_drift, std::fabs(energy(s) - E0));
  }
  r.s = s;
  return r;
}

// |x - expected| <= tol, with no relative slack (Catch's Approx adds 100 float epsilons otherwise).
Approx within(double expected, double tol) {
  return Approx(expected).epsilon(0).margin(tol);
}

// The error an adaptive integration may commit: each accepted step keeps its local error below
// atol + rtol |y| <= atol + rtol y_max, and with f = 0 free flight (u linear in t) is integrated
// exactly, so only the steps of the contact count; a velocity error made there is carried for
// `flight` time units into u.
double error_bound(const PenaltyParams& p, const Run& r, double y_max, double flight) {
  return (1 + flight) * static_cast<double>(r.contact_ode_steps) * (p.atol + p.rtol * y_max);
}

}  // namespace

TEST_CASE("penalty: a contact is half a period of the oscillator, u(10) = 5 - pi/sqrt(c_N)",
          "[penalty]") {
  // u0 = 5, v0 = -1, f = 0: the floor is reached at t = 5, left at 5 + pi/sqrt(c_N) with v = +1,
  // so u(10) = 10 - 5 - pi/sqrt(c_N).
  const Model model{0.0, 0.0, {}};
  const double h = 0.01;
  for (const char* stepper : {"rk8pd", "msbdf"}) {
    for (double c_N : {1e4, 1e6}) {
      CAPTURE(stepper, c_N);
      const PenaltyParams p{c_N, stepper, 1e-10, 1e-12};
      Penalty pen(model, h, p);
      const Run r = run(pen, model, c_N, {5.0, -1.0}, h, 0, 1000);
      REQUIRE(r.converged);
      const double bound = error_bound(p, r, 5.0, 5.0);
      CAPTURE(r.contact_ode_steps, bound);
      CHECK(r.s.u == within(5.0 - kPi / std::sqrt(c_N), bound));
      CHECK(r.s.v == within(1.0, bound / 5));
      CHECK(r.min_u >= -1.0 / std::sqrt(c_N) - bound);  // never deeper than the closed form
      CHECK(r.max_energy_drift <= bound);
    }
  }
}

TEST_CASE("penalty: every GSL stepper resolves the bounce within its tolerance", "[penalty]") {
  const Model model{0.0, 0.0, {}};
  const double h = 0.01, c_N = 1e6;
  for (const char* stepper : {"rk8pd", "rkf45", "rkck", "rk4", "rk2", "msbdf", "msadams", "rk4imp",
                              "rk2imp", "rk1imp", "bsimp"}) {
    CAPTURE(stepper);
    const PenaltyParams p{c_N, stepper, 1e-7, 1e-9};
    Penalty pen(model, h, p);
    const Run r = run(pen, model, c_N, {5.0, -1.0}, h, 0, 1000);
    REQUIRE(r.converged);
    CHECK(r.s.u == within(5.0 - kPi / std::sqrt(c_N), error_bound(p, r, 5.0, 5.0)));
  }
}

TEST_CASE("penalty: N^l >= 0 and h sum N^l = v(T) - v(0) - f T, with gravity and phi != 0",
          "[penalty]") {
  // Five bounces of 0.5 under f = -1. The impulse identity is exact up to rounding: v - P - f t
  // is a linear invariant of every Runge-Kutta and multistep method.
  const Model model{0.5, -1.0, {}};
  const double h = 0.01, T = 10, c_N = 1e6;
  for (const char* stepper : {"rk8pd", "msbdf", "rk4imp", "bsimp"}) {
    CAPTURE(stepper);
    Penalty pen(model, h, PenaltyParams{c_N, stepper, 1e-10, 1e-12});
    const State s0{1.0, 0.0};
    const Run r = run(pen, model, c_N, s0, h, 0, 1000);
    REQUIRE(r.converged);
    CHECK(r.min_N >= 0.0);
    CHECK(r.impulse == within(r.s.v - s0.v - model.f * T, 1e-12));
    CHECK(r.impulse > 5 * 2 * 0.99);               // five bounces, each reversing v = -1
    CHECK(r.min_u > 0.5 - 1.01 / std::sqrt(c_N));  // the depth of a v = -1 contact, f/c_N aside
    CHECK(r.max_energy_drift < 1e-6);              // compliance conserves energy; E(0) = 1
  }
}

TEST_CASE("C35: penalty's penetration depth falls like 1/sqrt(c_N)", "[penalty][claim]") {
  // From the floor with v0 = -1 and h a sixteenth of the contact, so that the grid hits the
  // deepest point (l = 8) and the exit (l = 16).
  const Model model{0.0, 0.0, {}};
  double previous_depth = 0;
  for (double c_N : {1e4, 1e6, 1e8, 1e10, 1e12}) {
    CAPTURE(c_N);
    const double w = std::sqrt(c_N), h = kPi / (16 * w);
    Penalty pen(model, h, PenaltyParams{c_N, "rk8pd", 1e-12, 1e-12 / w});
    const Run r = run(pen, model, c_N, {0.0, -1.0}, h, 0, 16);
    REQUIRE(r.converged);
    const double depth = -r.min_u;
    CHECK(depth * w == Approx(1.0).epsilon(1e-9));
    CHECK(r.s.v == Approx(1.0).epsilon(1e-9));
    if (previous_depth > 0) CHECK(previous_depth / depth == Approx(10.0).epsilon(1e-9));
    previous_depth = depth;
  }
}

TEST_CASE("penalty: initialize restarts the integration, also for a multistep method",
          "[penalty]") {
  // Restarting at t = 3 from u = 1, v = -1 moves the contact to t = 4, so u(10) = 6 - pi/w.
  // msbdf ignores the y it is given once started: initialize() must reset its driver.
  const Model model{0.0, 0.0, {}};
  const double h = 0.01, c_N = 1e6;
  for (const char* stepper : {"rk8pd", "msbdf"}) {
    CAPTURE(stepper);
    const PenaltyParams p{c_N, stepper, 1e-10, 1e-12};
    Penalty pen(model, h, p);
    REQUIRE(run(pen, model, c_N, {5.0, -1.0}, h, 0, 300).converged);
    const Run r = run(pen, model, c_N, {1.0, -1.0}, h, 300, 1000);
    REQUIRE(r.converged);
    CHECK(r.s.u == within(6.0 - kPi / std::sqrt(c_N), error_bound(p, r, 5.0, 6.0)));
  }
}

TEST_CASE("penalty: a moved Penalty carries on its integration unchanged", "[penalty]") {
  const Model model{0.0, 0.0, {}};
  const double h = 0.01, c_N = 1e6;
  const PenaltyParams p{c_N, "msbdf", 1e-10, 1e-12};
  Penalty reference(model, h, p);
  const State expected = run(reference, model, c_N, {5.0, -1.0}, h, 0, 1000).s;

  Penalty a(model, h, p);
  State s = run(a, model, c_N, {5.0, -1.0}, h, 0, 450).s;  // stops just before the contact
  Penalty b(std::move(a));
  s = run(b, model, c_N, s, h, 450, 502, true).s;  // stops inside it
  Penalty c(model, h, PenaltyParams{});
  c = std::move(b);
  s = run(c, model, c_N, s, h, 502, 1000, true).s;
  CHECK(s.u == expected.u);
  CHECK(s.v == expected.v);
}

TEST_CASE("penalty: a step GSL cannot complete reports non-convergence and keeps the state",
          "[penalty]") {
  const Model model{0.0, 0.0, {}};
  SECTION("a tolerance below rounding") {
    Penalty pen(model, 0.01, PenaltyParams{1e6, "rk8pd", 1e-300, 1e-300});
    State s{0.001, -1.0};
    pen.initialize(s, 0);
    const StepInfo info = pen.do_step(s, 0);
    CHECK_FALSE(info.converged);
    CHECK(s.u == 0.001);
    CHECK(s.v == -1.0);
    CHECK(info.contact_force == 0.0);
  }
  SECTION("a contact shorter than the resolution of t; then a fresh start recovers") {
    const double c_N = 1e15;  // a contact of 1e-7 at t = 1e8, where ulp(t) = 1.5e-8
    Penalty pen(model, 1.0, PenaltyParams{c_N, "rk8pd", 1e-10, 1e-12});
    State s{0.0, -1.0};
    pen.initialize(s, 100'000'000);
    CHECK_FALSE(pen.do_step(s, 100'000'000).converged);
    CHECK(s.u == 0.0);
    CHECK(s.v == -1.0);
    // initialize() restarts the driver from a new state.
    s = {0.5, -1.0};
    pen.initialize(s, 0);
    const StepInfo info = pen.do_step(s, 0);
    CHECK(info.converged);
    CHECK(s.u == within(0.5 - kPi / std::sqrt(c_N), 1e-8));
    CHECK(s.v == within(1.0, 1e-8));
    CHECK(info.contact_force == within(2.0, 1e-8));  // the impulse 2 |v| over h = 1
  }
  SECTION("a non-finite state") {
    Penalty pen(model, 0.01, PenaltyParams{});
    State s{std::numeric_limits<double>::quiet_NaN(), -1.0};
    pen.initialize(s, 0);
    CHECK_FALSE(pen.do_step(s, 0).converged);
    CHECK(s.v == -1.0);
  }
}

namespace {

impact::Scene penalty_scene(const std::string& method_keys) {
  return impact::parse_scene(
      "[initial]\nu0 = 5\nv0 = -1\n[time]\nT = 10\nh = 0.01\n[method]\nname = \"penalty\"\n" +
          method_keys,
      "test.toml");
}

// The SceneError message that reading [method] gives, or "" when it is accepted.
std::string read_error(const std::string& method_keys) {
  try {
    penalty_scene(method_keys);
  } catch (const impact::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("penalty: the scene reader reads stiffness, stepper, rtol and atol within their ranges",
          "[penalty]") {
  using Catch::Matchers::Contains;
  {
    const impact::Scene scene = penalty_scene("");
    const PenaltyParams p = std::get<PenaltyParams>(scene.method);
    CHECK(p.stiffness == 1e6);
    CHECK(p.stepper == "rk8pd");
    CHECK(p.rtol == 1e-10);
    CHECK(p.atol == 1e-12);
  }
  {
    const impact::Scene scene =
        penalty_scene("stiffness = 1e15\nstepper = \"msbdf\"\nrtol = 1e-8\natol = 1\n");
    const PenaltyParams p = std::get<PenaltyParams>(scene.method);
    CHECK(p.stiffness == 1e15);
    CHECK(p.stepper == "msbdf");
    CHECK(p.rtol == 1e-8);
    CHECK(p.atol == 1.0);
    CHECK(std::holds_alternative<Penalty>(impact::make_stepper(scene)));
  }
  for (const char* name : {"rk8pd", "rkf45", "rkck", "rk4", "msbdf", "rk4imp", "bsimp", "rk2imp"})
    CHECK(read_error("stepper = \"" + std::string(name) + "\"\n").empty());

  CHECK_THAT(read_error("stepper = \"euler\"\n"),
             Contains("test.toml") && Contains("method.stepper") && Contains("rk8pd") &&
                 Contains("msbdf") && Contains("bsimp"));
  CHECK_THAT(read_error("stepper = 4\n"), Contains("method.stepper"));
  for (const char* bad : {"0", "-1", "1e16", "\"big\""}) {
    CAPTURE(bad);
    CHECK_THAT(read_error("stiffness = " + std::string(bad) + "\n"), Contains("method.stiffness"));
  }
  CHECK_THAT(read_error("stiffness = 0\n"), Contains("(0, 1e+15]"));
  for (const char* key : {"rtol", "atol"}) {
    for (const char* bad : {"0", "2", "-1e-10"}) {
      CAPTURE(key, bad);
      CHECK_THAT(read_error(std::string(key) + " = " + bad + "\n"),
                 Contains("method." + std::string(key)) && Contains("(0, 1]"));
    }
  }
  CHECK_THAT(read_error("stifness = 1e8\n"), Contains("stiffness") && Contains("stepper"));
}

// RK4 for u'' = force(u) from (u0, v0) over [0, T] in n steps; returns the minimum of u, u(T) and
// the largest distance from `reference(t)` (the Signorini solution, or a closed form).
struct Orbit {
  double min_u, u_end, v_end, max_dev;
};
template <class Force, class Reference>
Orbit rk4(Force force, double u0, double v0, double T, int n, Reference reference) {
  const double dt = T / n;
  double u = u0, v = v0;
  Orbit o{u0, u0, v0, std::fabs(u0 - reference(0.0))};
  for (int i = 0; i < n; ++i) {
    const double k1u = v, k1v = force(u);
    const double k2u = v + 0.5 * dt * k1v, k2v = force(u + 0.5 * dt * k1u);
    const double k3u = v + 0.5 * dt * k2v, k3v = force(u + 0.5 * dt * k2u);
    const double k4u = v + dt * k3v, k4v = force(u + dt * k3u);
    u += dt / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
    v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    o.min_u = std::fmin(o.min_u, u);
    o.max_dev = std::fmax(o.max_dev, std::fabs(u - reference((i + 1) * dt)));
  }
  o.u_end = u;
  o.v_end = v;
  return o;
}

TEST_CASE(
    "C4: error in the paper: with N = c_N max(u - phi, 0) a particle falling toward the floor "
    "is pushed away and never reaches it: the law is N = c_N max(phi - u, 0)",
    "[penalty][claim]") {
  // Section 5 writes N = p(u - phi), p(r) = c_N max(r, 0). A particle at u0 = 1 above the floor
  // phi = 0, falling at v0 = -1 with f = 0, reaches the floor at t = 1 and (Signorini, COR = 1)
  // leaves it: u(t) = |1 - t|. Under the printed law u'' = c_N u while u > 0, so
  // u = a e^{kt} + b e^{-kt}, k = sqrt(c_N), a = (1 - 1/k)/2, b = (1 + 1/k)/2 > 0: the particle
  // turns around within 1/c_N of the start, at height sqrt(1 - 1/c_N), and is flung away.
  const double c_N = 1e6, k = std::sqrt(c_N), phi = 0.0;
  auto printed = [&](double u) { return c_N * std::fmax(u - phi, 0.0); };
  auto corrected = [&](double u) { return c_N * std::fmax(phi - u, 0.0); };
  auto signorini = [](double t) { return std::fabs(1.0 - t); };
  const double a = (1 - 1 / k) / 2, b = (1 + 1 / k) / 2;
  auto closed_form = [&](double t) { return a * std::exp(k * t) + b * std::exp(-k * t); };

  // The printed law over the first 0.01 s (k t = 10): the integration follows its closed form,
  // the particle never comes closer to the floor than sqrt(1 - 1/c_N) and ends 1e4 m up, flying
  // away at k u, while the Signorini particle has just fallen 0.01 m.
  const Orbit pushed = rk4(printed, 1.0, -1.0, 0.01, 10000, closed_form);
  CHECK(pushed.max_dev <= 1e-8 * closed_form(0.01));
  CHECK(pushed.min_u >= std::sqrt(1 - 1 / c_N) - 1e-9);
  CHECK(pushed.u_end > 1e4);
  CHECK(pushed.v_end > 0.99 * k * pushed.u_end);
  CHECK(std::fabs(pushed.u_end - signorini(0.01)) > 1e4);

  // The corrected law over [0, 2]: the bounce of the Signorini solution, late by the contact's
  // duration pi/k and penetrating 1/k, with the velocity given back (energy conserved).
  const Orbit bounce = rk4(corrected, 1.0, -1.0, 2.0, 200000, signorini);
  CHECK(bounce.min_u == Approx(-1 / k).epsilon(1e-3));
  CHECK(bounce.max_dev <= 4 / k);
  CHECK(bounce.max_dev >= 1 / k);  // compliance is not Signorini: the lag pi/k shows
  // (RK4 steps over the kinks of max(., 0) at the contact's ends: 1e-5 is its error, << 1/k.)
  CHECK(bounce.v_end == within(1.0, 1e-5));
  CHECK(bounce.u_end == within(1.0 - kPi / k, 1e-5));

  // impact's Penalty applies the corrected law: no force in free flight, a push on penetration.
  const Model model{phi, 0.0, {}};
  Penalty pen(model, 1e-3, PenaltyParams{c_N, "rk8pd", 1e-10, 1e-12});
  State above{5.0, -1.0};
  pen.initialize(above, 0);
  CHECK(pen.do_step(above, 0).contact_force == 0.0);
  State penetrating{-1e-4, -1.0};
  pen.initialize(penetrating, 0);
  CHECK(pen.do_step(penetrating, 0).contact_force > 0.0);
}

TEST_CASE("penalty: a run stops, with its reason, when it has used up its budget of ODE steps",
          "[penalty]") {
  // A particle resting on a stiff floor with an implicit stepper takes ~1e5 ODE steps per grid
  // step; unbounded, T = 1 ran for minutes. The budget caps the whole run, not one grid step.
  const Model model{0.0, -9.80665, {}};
  PenaltyParams p{1e12, "rk2imp", 1e-10, 1e-12};
  p.max_ode_steps = 20000;
  Penalty pen(model, 1e-3, p);
  State s{0.0, 0.0};
  pen.initialize(s, 0);
  bool stopped = false;
  for (std::int64_t l = 0; l < 1000 && !stopped; ++l) stopped = !pen.do_step(s, l).converged;
  CHECK(stopped);
  CHECK_THAT(pen.failure_reason(), Catch::Matchers::Contains("budget of ODE steps"));
  // The automatic budget (0): 1e6 plus 1000 per grid step, enough for free flight.
  Penalty free(model, 1e-3, PenaltyParams{});
  State above{5.0, 0.0};
  free.initialize(above, 0);
  for (std::int64_t l = 0; l < 1000; ++l) REQUIRE(free.do_step(above, l).converged);
}
