// The time-steppers' step mean of a force expression (step_quadrature.hpp): its error under
// control for a force faster than the step, and a step it cannot resolve (a pole, a force far
// too fast) refused naming where.
#include <gsl/gsl_integration.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "cli_support.hpp"
#include "impact/forces/force.hpp"
#include "impact/forces/step_quadrature.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"

using Catch::Matchers::Contains;
using impact::Model;
using impact::State;
using namespace impact::testing;

namespace {

State end_state(const Model& model, const impact::MethodParams& method, const State& initial,
                const impact::Grid& grid) {
  impact::AnyStepper stepper = impact::make_stepper(model, grid.h, method);
  State end = initial;
  impact::simulate(stepper, initial, grid,
                   [&](std::int64_t, const State& s, const impact::StepInfo&) { end = s; });
  return end;
}

}  // namespace

TEST_CASE("A force faster than the step: each step's mean is its integral, not an aliased sum",
          "[forcing][regression]") {
  // f = -9.80665 + 1e4 sin(1e5 t), h = 1e-3: 16 periods per step. 16-point Gauss-Legendre aliased
  // it: direct gave u_T = 72.86 where its harmonic twin (exact step impulses) gives 80.59. The
  // step means now meet 1e-12 of h max|f| = 1e-11 each; over 2000 steps, even added up, that is
  // 2e-8 in v and 4e-8 in u (measured 8e-12).
  Model expression;
  expression.expression = "-9.80665 + 1e4 * sin(1e5 * t)";
  Model harmonic;
  harmonic.f = -9.80665;
  harmonic.harmonic = impact::Harmonic{1e4, 1e5, 0.0};
  const State initial{100.0, 0.0};
  const impact::Grid grid{1e-3, 2000};
  for (const impact::MethodParams& method : {impact::MethodParams(impact::DirectParams{}),
                                             impact::MethodParams(impact::FbNewtonParams{}),
                                             impact::MethodParams(impact::MoreauJeanParams{})}) {
    INFO(impact::method_name(method));
    const State a = end_state(expression, method, initial, grid);
    const State b = end_state(harmonic, method, initial, grid);
    CHECK(a.u == Approx(b.u).margin(4e-8));
    CHECK(a.v == Approx(b.v).margin(2e-8));
  }
  // Another fast force, in free flight: v_T = v0 + the integral of f over [0, T] (the impulse
  // identity (4-9) with N = 0), whatever the steps.
  Model two;
  two.expression = "-9.80665 + 300 * sin(4e4 * t) + 100 * cos(2.3e5 * t)";
  const double T = grid.end();
  const double integral =
      -9.80665 * T + 300 / 4e4 * (1 - std::cos(4e4 * T)) + 100 / 2.3e5 * std::sin(2.3e5 * T);
  CHECK(end_state(two, impact::DirectParams{}, initial, grid).v == Approx(integral).margin(2e-9));
}

TEST_CASE("A step the quadrature cannot resolve stops the run naming where",
          "[forcing][regression]") {
  // A pole inside a step, or a force 1e9 times faster than the step: the time-steppers ran to
  // exit 0 with finite numbers (1 / (t - 0.5)). Now exit 1, no output, t named.
  TempDir dir;
  dir.write("s.toml", "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 2.0\nh = 0.001\n");
  for (const std::string method : {"direct", "fb_newton", "moreau_jean"}) {
    const std::string run = "run s.toml -o out.csv --set method.name=" + method;
    for (const std::string pole : {"1/(t-0.5)", "1/(t-0.5)^2", "1/(t-0.5001)", "1/tan(t-0.5)"})
      CHECK_FAILS_CLEANLY(dir, run + " --set 'force.expression=\"" + pole + "\"'", 1,
                          Contains("at t = 0.5") && Contains("(no output file written)"));
    CHECK_FAILS_CLEANLY(dir, run + " --set 'force.expression=\"-9.8 + 1e3 * sin(1e12 * t)\"'", 1,
                        Contains("not resolved over [0, 0.001]") &&
                            Contains("use a smaller time.h, or method event_driven"));
  }
}

TEST_CASE("A resolved step keeps the 16-point rule's value bit for bit", "[forcing]") {
  // What the shipped scenes see: gsl_integration_glfixed's sum, not another estimate.
  Model m;
  m.expression = "-9.80665 + 4 * tanh(5 * sin(2 * t))";
  const impact::ForceFunction f(m);
  for (const double h : {1e-3, 1e-2, 0.1})
    for (double t = 0; t < 3; t += 0.37) {
      const double rule = [&] {
        gsl_function F{[](double x, void* self) {
                         return static_cast<const impact::ForceFunction*>(self)->at(x);
                       },
                       const_cast<impact::ForceFunction*>(&f)};
        gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(16);
        const double value = gsl_integration_glfixed(&F, t, t + h, table);
        gsl_integration_glfixed_table_free(table);
        return value;
      }();
      CHECK(f.integral(t, t + h) == rule);
    }
}
