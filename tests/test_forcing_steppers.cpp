// The time-steppers with a time-dependent body force f(t) (scheme_flight.hpp): the constant path
// unchanged bit for bit, the impulse identity (4-9) with the integral of f, second order in free
// flight, an expression force against the same harmonic force, the grid phasor's drift, and the
// ensemble's refusal.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "analysis/fit.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/forces/force.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/summary.hpp"
#include "trajectory_support.hpp"

using namespace impact;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using testing::Row;

std::vector<Row> trajectory(const Model& model, const State& initial, const Grid& grid,
                            const MethodParams& method) {
  return testing::trajectory(make_stepper(model, grid.h, method), initial, grid);
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The ball on a table vibrating as a sin(omega t) in the table's frame, Gamma = a omega^2 / g
// = 1.5.
Model table_model() {
  Model model;
  model.f = -9.80665;
  model.harmonic = Harmonic{14.71, 62.831853, 0.3};
  return model;
}

std::string table_expression() {
  return "-9.80665 + 14.71 * sin(62.831853 * t + 0.3)";
}

// The time-steppers whose step mean enters (4-1)-(4-3) or the velocity update.
std::vector<MethodParams> scheme_methods() {
  return {DirectParams{}, DirectParams{FreeFlightForm::paper}, FbNewtonParams{},
          FbNewtonParams{.free_flight = FreeFlightForm::paper}, MoreauJeanParams{}};
}

}  // namespace

TEST_CASE("A harmonic part of amplitude 0 leaves every scheme bit-identical to the constant force",
          "[forcing][regression]") {
  // The step mean is split as f + I^l / h with I^l = 0 * (...) = +-0, which adds nothing.
  for (const std::optional<double> cor : {std::optional<double>{}, std::optional<double>{0.75}}) {
    Model constant;
    constant.f = -9.80665;
    constant.cor = cor;
    Model zero = constant;
    zero.harmonic = Harmonic{0.0, 62.831853, 0.3};
    const Grid grid{1e-3, 8000};  // bounces from 5 m, and rests with COR
    for (const MethodParams& method : scheme_methods()) {
      INFO(method_name(method) << (cor ? " with COR" : ""));
      const auto a = trajectory(constant, {5.0, -1.0}, grid, method);
      const auto b = trajectory(zero, {5.0, -1.0}, grid, method);
      std::int64_t differing = 0, contacts = 0;
      for (std::size_t l = 0; l < a.size(); ++l) {
        differing += !same_bits(a[l].s.u, b[l].s.u) || !same_bits(a[l].s.v, b[l].s.v) ||
                     !same_bits(a[l].info.contact_force, b[l].info.contact_force);
        contacts += a[l].info.contact_force > 0;
      }
      CHECK(contacts > 0);
      CHECK(differing == 0);
    }
  }
}

TEST_CASE("Impulse identity with f(t): h sum N^l = v^n - v^0 - int_0^T f", "[forcing][property]") {
  // Without COR, each scheme's velocity changes by h f^l = int over the step of f plus h N^l, so
  // the identity holds up to rounding: direct and fb_newton round once per contact step (their
  // free flight is in closed form from the last contact), moreau_jean once per step. The bound:
  // 4 eps per rounding event of the velocity scale V = max |v| + |a|/omega + |f| T.
  Model model = table_model();
  model.phi = 0.0;
  const Grid grid{1e-3, 5000};
  const State initial{0.3, 0.0};
  const double integral = ForceFunction(model).integral(0.0, grid.end());
  for (const MethodParams& method : scheme_methods()) {
    INFO(method_name(method));
    const auto rows = trajectory(model, initial, grid, method);
    double impulse = 0, max_v = 0;
    std::int64_t contacts = 0;
    for (const Row& r : rows) {
      impulse += grid.h * r.info.contact_force;
      max_v = std::fmax(max_v, std::fabs(r.s.v));
      contacts += r.info.contact_force > 0;
    }
    const double residual = impulse - (rows.back().s.v - initial.v - integral);
    const double V = max_v + 14.71 / 62.831853 + 9.80665 * grid.end();
    const bool stepped =
        std::holds_alternative<MoreauJeanParams>(method) ||
        method == MethodParams{DirectParams{FreeFlightForm::paper}} ||
        method == MethodParams{FbNewtonParams{.free_flight = FreeFlightForm::paper}};
    const double events = static_cast<double>(stepped ? grid.steps : contacts + 1);
    INFO("contact steps " << contacts << ", residual " << residual);
    CHECK(contacts > 5);
    CHECK(std::fabs(residual) <= 4 * kEps * events * V);
  }
}

TEST_CASE("Free flight under a harmonic force is second order against ForceFunction::flight",
          "[forcing][property]") {
  // The scheme's free flight is the trapezoidal rule of the exact velocity (scheme_flight.hpp):
  // u is off by (a/w)|1/w - c||sin theta_m - sin theta_a| = O(a w h^2), v only by rounding. The
  // floor is 100 m down, never reached in T = 1. Order from the maximum error over the grid at
  // h and h/2, expected 2 up to the next term of the expansion, O((w h)^2) relative: [1.95, 2.05]
  // for w h <= 0.063.
  Model harmonic = table_model();
  harmonic.phi = -100.0;
  Model expression = harmonic;
  expression.f = 0.0;
  expression.harmonic.reset();
  expression.expression = table_expression();
  const State initial{0.0, 1.0};
  const ForceFunction force(harmonic);
  const std::vector<MethodParams> methods = {DirectParams{}, FbNewtonParams{}, MoreauJeanParams{}};
  for (const Model& model : {harmonic, expression})
    for (const MethodParams& method : methods) {
      INFO(method_name(method) << (model.expression.empty() ? " harmonic" : " expression"));
      std::vector<double> errors;
      for (double h : {1e-3, 5e-4, 2.5e-4}) {
        const Grid grid = Grid::covering(1.0, h);
        const auto rows = trajectory(model, initial, grid, method);
        double max_error = 0;
        for (std::size_t l = 0; l < rows.size(); ++l) {
          const State exact = force.flight(initial, 0.0, grid.t(static_cast<std::int64_t>(l)));
          max_error = std::fmax(max_error, std::fabs(rows[l].s.u - exact.u));
        }
        errors.push_back(max_error);
      }
      for (std::size_t k = 1; k < errors.size(); ++k) {
        const double order = std::log2(errors[k - 1] / errors[k]);
        INFO("error " << errors[k - 1] << " -> " << errors[k] << ", order " << order);
        CHECK(order >= 1.95);
        CHECK(order <= 2.05);
      }
    }
}

TEST_CASE("With impacts (COR 0.75) under a harmonic force the time-steppers are first order",
          "[forcing][property]") {
  // The vibrating table of table_model() from u = 0.3 m at rest, T = 1 s: three impacts (t = 0.27,
  // 0.66, 0.92 s), no sticking. Reference: the event-driven solution (exact) on the same grid.
  // Each impact is placed to within a step, so the error is O(h); how far within depends on where
  // the impact falls between grid points, which scatters the errors about the line (the fit's
  // standard error is 0.07-0.13). Least-squares order of sup |u - u_exact| over 20 log-spaced h
  // in [1e-5, 1e-3]: 1 within 0.25, two standard errors.
  Model model = table_model();
  model.cor = 0.75;
  const State initial{0.3, 0.0};
  const std::vector<double> steps = log_spaced(1e-3, 1e-5, 20);
  for (const MethodParams& method : {MethodParams{DirectParams{}}, MethodParams{FbNewtonParams{}},
                                     MethodParams{MoreauJeanParams{}}}) {
    INFO(method_name(method));
    std::vector<double> errors;
    for (double h : steps) {
      const Grid grid = Grid::covering(1.0, h);
      const auto rows = trajectory(model, initial, grid, method);
      const auto exact = trajectory(model, initial, grid, ExactParams{});
      double sup = 0;
      for (std::size_t l = 0; l < rows.size(); ++l)
        sup = std::fmax(sup, std::fabs(rows[l].s.u - exact[l].s.u));
      errors.push_back(sup);
    }
    const OrderFit fit = fit_order(steps, errors);
    INFO("order " << fit.order << " +- " << fit.order_standard_error);
    CHECK(fit.points == steps.size());
    CHECK(std::fabs(fit.order - 1) <= 0.25);
  }
}

TEST_CASE("An expression force equal to the harmonic one gives the same trajectory",
          "[forcing][regression]") {
  // Both give the same discrete solution: the harmonic part summed in closed form, the expression
  // stepped with its step integrals (16-point Gauss-Legendre, exact to rounding for sin over
  // w h = 0.063). They differ by rounding that the stepped sums accumulate, about eps per step of
  // the velocity scale (a/w + |f| T ~ 50 m/s): at most 5000 eps 50 = 5.5e-11 if every rounding
  // had the same sign, and each impact carries it on (restitution 0.75 contracts it). Tolerance
  // 1e-10 m, m/s.
  Model harmonic = table_model();
  harmonic.cor = 0.75;
  Model expression = harmonic;
  expression.f = 0.0;
  expression.harmonic.reset();
  expression.expression = table_expression();
  const Grid grid{1e-3, 5000};
  for (const MethodParams& method : {MethodParams{DirectParams{}}, MethodParams{FbNewtonParams{}},
                                     MethodParams{MoreauJeanParams{}}}) {
    INFO(method_name(method));
    const auto a = trajectory(harmonic, {0.3, 0.0}, grid, method);
    const auto b = trajectory(expression, {0.3, 0.0}, grid, method);
    double max_u = 0, max_v = 0;
    std::int64_t contacts = 0;
    for (std::size_t l = 0; l < a.size(); ++l) {
      max_u = std::fmax(max_u, std::fabs(a[l].s.u - b[l].s.u));
      max_v = std::fmax(max_v, std::fabs(a[l].s.v - b[l].s.v));
      contacts += a[l].info.contact_force > 0;
    }
    INFO("max |du| " << max_u << ", max |dv| " << max_v);
    CHECK(contacts > 10);
    CHECK(max_u <= 1e-10);
    CHECK(max_v <= 1e-10);
  }
}

TEST_CASE("The grid phasor is within its error bound of cos and sin of omega t_l + phase",
          "[forcing][property]") {
  // scheme_flight.hpp: (4 n - 3) u per component, u = eps/2, n the factors other than (1, 0)
  // (the phase and the non-zero base-64 digits of l), against (cos, sin) of the sum of the
  // factors' angles, in long double (64-bit mantissa: its own error, ~1e-19 per factor, is
  // negligible against u = 1.1e-16).
  const Harmonic w{1.0, 62.831853, 0.3};
  const double h = 1e-3;
  GridPhasor phasor(w, h);
  double worst_ratio = 0;
  const auto check = [&](std::int64_t l) {
    // The product of the factors (cos a, sin a), each angle a as the phasor's table has it: the
    // sum of the angles reduced exactly, where a sum of the angles in long double would not be
    // (they reach 1e14 rad far along the grid).
    long double c = std::cos(static_cast<long double>(w.phase));
    long double s = std::sin(static_cast<long double>(w.phase));
    int factors = 1;
    for (int k = 0; k < GridPhasor::kLevels; ++k) {
      const int d = static_cast<int>((l >> (GridPhasor::kDigitBits * k)) & (GridPhasor::kBase - 1));
      const long double a = phasor.angle(k, d);
      const long double ck = std::cos(a), sk = std::sin(a);
      const long double c_next = c * ck - s * sk;
      s = s * ck + c * sk;
      c = c_next;
      factors += d != 0;
    }
    const double error = std::fmax(std::fabs(static_cast<double>(phasor.cos() - c)),
                                   std::fabs(static_cast<double>(phasor.sin() - s)));
    worst_ratio = std::fmax(worst_ratio, error / ((4 * factors - 3) * kEps / 2));
  };
  for (std::int64_t l = 0; l < 15000; ++l, phasor.advance()) check(l);
  // Far along the grid: every digit non-zero.
  const std::int64_t far = 0x1F7A5B3C2D1E3FLL;
  phasor.seek(far);
  for (std::int64_t l = far; l < far + 200; ++l, phasor.advance()) check(l);
  INFO("worst error / bound " << worst_ratio);
  CHECK(worst_ratio <= 1.0);
  // A restart at any l gives the values of an uninterrupted run (a function of l alone).
  GridPhasor restarted(w, h), straight(w, h);
  restarted.seek(1000);
  for (int l = 0; l < 1000; ++l) straight.advance();
  for (int j = 0; j < 200; ++j, restarted.advance(), straight.advance()) {
    CHECK(same_bits(restarted.cos(), straight.cos()));
    CHECK(same_bits(restarted.sin(), straight.sin()));
  }
}

TEST_CASE(
    "The ensemble refuses a time-dependent force and the sweep summary does not call it constant",
    "[forcing][regression]") {
  const Model model = table_model();
  const std::vector<Model> models{Model{}, model};
  const std::vector<State> initial(2, State{1.0, 0.0});
  CHECK_THROWS_WITH(Ensemble(EnsembleMethod::direct, models, initial, 1e-3),
                    Catch::Contains("particle 1 has a time-dependent body force"));
  const Scene scene = make_scene(model, {1.0, 0.0}, 1.0, 1e-3, DirectParams{});
  CHECK_FALSE(ensemble_kind(scene).has_value());
  // E = v^2/2 - f u (3-1) is not an energy of (2-1) with f(t): the summary gives the E channel's
  // v^2/2 - f(0) u(0) - W instead (work_energy.hpp).
  const PointSummary point = summarize(scene, false).summary;
  CHECK(std::isfinite(point.energy_final));
  CHECK_FALSE(same_bits(point.energy_final, energy(model, point.final)));
}

TEST_CASE("penalty takes f(t): free flight within its tolerance, the impulse invariant",
          "[forcing][penalty][property]") {
  // The right-hand side evaluates f(t); the free flight is then the exact one up to the ODE
  // stepper's error control: rtol = 1e-10 per ODE step, ~1000 steps, |u| <= 2: 1e-7 m at most.
  Model model = table_model();
  model.phi = -100.0;
  const ForceFunction force(model);
  const Grid grid{1e-3, 1000};
  const auto flight = trajectory(model, {0.0, 1.0}, grid, PenaltyParams{});
  double max_error = 0;
  for (std::size_t l = 0; l < flight.size(); ++l)
    max_error =
        std::fmax(max_error,
                  std::fabs(flight[l].s.u -
                            force.flight({0.0, 1.0}, 0.0, grid.t(static_cast<std::int64_t>(l))).u));
  INFO("free flight error " << max_error);
  CHECK(max_error <= 1e-7);
  // With contacts: v - P - int_0^t f is a linear invariant of the ODE (penalty.cpp), kept up to
  // the error of integrating f(t) (rtol 1e-10 of the velocity scale ~50 m/s per ODE step) and
  // rounding: 1e-6 m/s over 2 s.
  model.phi = 0.0;
  const Grid bouncing{1e-3, 2000};
  const auto rows = trajectory(model, {0.3, 0.0}, bouncing, PenaltyParams{});
  double impulse = 0;
  std::int64_t contacts = 0;
  for (const Row& r : rows) {
    impulse += bouncing.h * r.info.contact_force;
    contacts += r.info.contact_force > 0;
  }
  const double residual = impulse - (rows.back().s.v - 0.0 - force.integral(0.0, bouncing.end()));
  INFO("contact steps " << contacts << ", residual " << residual);
  CHECK(contacts > 5);
  CHECK(std::fabs(residual) <= 1e-6);
}

TEST_CASE("An expression force that is not finite during the run stops it naming t",
          "[forcing][regression]") {
  // 1/(t - 0.25) is finite at t = 0 and infinite at the grid time 0.25 = 16 h, where the ODE
  // stepper evaluates it.
  Model model;
  model.phi = -100.0;
  model.expression = "1/(t - 0.25)";
  AnyStepper stepper = make_stepper(model, 1.0 / 64, PenaltyParams{});
  CHECK_THROWS_WITH(simulate(stepper, {0.0, 0.0}, Grid{1.0 / 64, 64},
                             [](std::int64_t, const State&, const StepInfo&) {}),
                    Catch::Contains("at t = 0.25"));
  // sqrt(0.3 - t) is NaN after t = 0.3, where a step's Gauss-Legendre nodes fall.
  model.expression = "sqrt(0.3 - t)";
  for (const MethodParams& method : scheme_methods()) {
    INFO(method_name(method));
    AnyStepper scheme = make_stepper(model, 1.0 / 64, method);
    CHECK_THROWS_WITH(simulate(scheme, {0.0, 0.0}, Grid{1.0 / 64, 64},
                               [](std::int64_t, const State&, const StepInfo&) {}),
                      Catch::Contains("at t = 0.3"));
  }
}
