// A harmonic force a sin(omega t + phase) with omega tiny: its flight written without the factors
// a/omega and a/omega^2 (harmonic_series.hpp), so that it agrees with the constant force
// f + a sin(phase) where omega t is below rounding, and with the same force written as an
// expression otherwise.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "impact/forces/force.hpp"
#include "impact/forces/harmonic_series.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"

using impact::Model;
using impact::State;

namespace {

// The table of the report: u0 = 0.01, e = 0.5, f = -9.80665 + 14.71 sin(omega t + phase).
Model table(double omega, double phase) {
  Model m;
  m.f = -9.80665;
  m.cor = 0.5;
  m.harmonic = impact::Harmonic{14.71, omega, phase};
  return m;
}

// The same force as a constant (its value at t = 0) or as an expression.
Model frozen(const Model& m) {
  Model c = m;
  c.f += m.harmonic->amplitude * std::sin(m.harmonic->phase);
  c.harmonic.reset();
  return c;
}
Model written_out(const Model& m) {
  Model e = m;
  char text[200];
  std::snprintf(text, sizeof text, "%.17g + %.17g * sin(%.17g * t + %.17g)", m.f,
                m.harmonic->amplitude, m.harmonic->omega, m.harmonic->phase);
  e.expression = text;
  e.f = 0;
  e.harmonic.reset();
  return e;
}

std::vector<State> trajectory(const Model& model, const impact::MethodParams& method) {
  const impact::Grid grid{1e-4, 20000};
  impact::AnyStepper stepper = impact::make_stepper(model, grid.h, method);
  std::vector<State> out;
  impact::simulate(
      stepper, State{0.01, 0.0}, grid,
      [&](std::int64_t, const State& s, const impact::StepInfo&) { out.push_back(s); });
  return out;
}

double max_distance(const std::vector<State>& a, const std::vector<State>& b) {
  REQUIRE(a.size() == b.size());
  double d = 0;
  for (std::size_t l = 0; l < a.size(); ++l)
    d = std::fmax(d, std::fmax(std::fabs(a[l].u - b[l].u), std::fabs(a[l].v - b[l].v)));
  return d;
}

const impact::MethodParams kMethods[] = {impact::DirectParams{}, impact::FbNewtonParams{},
                                         impact::MoreauJeanParams{}, impact::ExactParams{}};

}  // namespace

TEST_CASE("A harmonic force with omega below rounding is the constant f + a sin(phase)",
          "[forcing][regression]") {
  // omega = 1e-20 and 1e-300: a omega t < 3e-19 over the 2 s, far below the rounding of f. It
  // used to give u_T = 524 287 m (direct, fb_newton: the phasor's rounding times a/omega^2),
  // max_u = 4.3e8 m at 1e-24 (exact's rotation) and N = inf at 1e-300. The two runs now differ by
  // the rounding of the split f + (a sin(phase) written out of the sum): measured < 1e-13.
  for (const double omega : {1e-20, 1e-24, 1e-300})
    for (const double phase : {0.0, 0.3})
      for (const auto& method : kMethods) {
        INFO("omega = " << omega << ", phase = " << phase << ", " << impact::method_name(method));
        const Model m = table(omega, phase);
        CHECK(max_distance(trajectory(m, method), trajectory(frozen(m), method)) < 1e-12);
      }
}

TEST_CASE("A slow harmonic force agrees with the same force written as an expression",
          "[forcing][regression]") {
  // omega = 1e-8 and 1e-4: the force moves by up to 3e-3 over the run, so the constant does not
  // stand in for it; each method against itself with the expression (its GL16 step means for the
  // time-steppers, event_driven for exact): the same discrete solution up to rounding, measured
  // below 2e-14. exact was 4.7e-7 off at 1e-8 and 2.6e-3 at 1e-12, direct 3.4e-7 at 1e-8.
  for (const double omega : {1e-12, 1e-8, 1e-4})
    for (const double phase : {0.0, 0.5, -0.3})
      for (const auto& method : kMethods) {
        INFO("omega = " << omega << ", phase = " << phase << ", " << impact::method_name(method));
        const Model m = table(omega, phase);
        const bool exact = std::holds_alternative<impact::ExactParams>(method);
        const impact::MethodParams reference =
            exact ? impact::MethodParams(impact::EventDrivenParams{}) : method;
        CHECK(max_distance(trajectory(m, method), trajectory(written_out(m), reference)) < 1e-12);
      }
}

TEST_CASE("The slow forms' terms are sin x / x and its kin to rounding", "[forcing]") {
  // Near the switch at x = 1/2 the closed forms lose at most 6 bits to 1 - cos x and x - sin x,
  // so series and closed forms agree within that.
  for (const double x : {0.3, 0.45, 0.4999}) {
    INFO("x = " << x);
    const impact::SlowAngle a = impact::slow_angle(x, std::sin(x), std::cos(x));
    const impact::SlowAngle b = impact::slow_angle_series(x);
    CHECK(b.s1 == Approx(a.s1).epsilon(4e-16));
    CHECK(b.c1 == Approx(a.c1).epsilon(1e-14));
    CHECK(b.c2 == Approx(a.c2).epsilon(1e-14));
    CHECK(b.s2 == Approx(a.s2).epsilon(1e-14));
  }
  // The limits at x = 0, so that omega = 0 is the constant force.
  const impact::SlowAngle zero = impact::slow_angle_series(0.0);
  CHECK(zero.s1 == 1.0);
  CHECK(zero.c2 == 0.5);
  CHECK(zero.c1 == 0.0);
  CHECK(zero.s2 == 0.0);
  // The integral of the harmonic part where a/omega overflows: a (t1 - t0) sin(phase).
  const impact::Harmonic w{14.71, 1e-310, 0.5};
  CHECK(impact::harmonic_integral(w, 0.0, 2.0) == Approx(14.71 * 2 * std::sin(0.5)));
}

TEST_CASE("A copied stepper with a slow harmonic force steps as the original, bit for bit",
          "[forcing][regression]") {
  // The copy of a stepper's force used to drop the slow forms (a copy went back to a/omega and
  // a/omega^2): a caller that copies a stepper got another trajectory.
  const impact::Grid grid{1e-4, 20000};
  const auto run = [&](auto stepper) {
    std::vector<State> out;
    impact::simulate(
        stepper, State{0.01, 0.0}, grid,
        [&](std::int64_t, const State& s, const impact::StepInfo&) { out.push_back(s); });
    return out;
  };
  for (const double omega : {1e-20, 1e-8}) {
    INFO("omega = " << omega);
    const Model m = table(omega, 0.3);
    const impact::DirectHarmonic direct(m, grid.h, impact::DirectParams{});
    const impact::FbNewton fb_newton(m, grid.h, impact::FbNewtonParams{});
    const impact::MoreauJeanHarmonic moreau_jean(m, grid.h, impact::MoreauJeanParams{});
    const auto copy_of = [](const auto& stepper) { return stepper; };
    CHECK(max_distance(run(copy_of(direct)), run(impact::DirectHarmonic(m, grid.h, {}))) == 0);
    CHECK(max_distance(run(copy_of(fb_newton)), run(impact::FbNewton(m, grid.h, {}))) == 0);
    CHECK(max_distance(run(copy_of(moreau_jean)), run(impact::MoreauJeanHarmonic(m, grid.h, {}))) ==
          0);
  }
}
