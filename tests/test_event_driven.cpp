// The method event_driven (event_driven.hpp, ode_flight.hpp): the exact solution for a force
// expression, by GSL odeiv2 rk8pd between impacts found by the certified search. Checked against
// the closed-form references (exact for the same force written as harmonic or constant), on a
// grazing impact, a lift-off time derived by hand and a chatter, and as the reference of
// measure_errors() for an expression.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/references/event_driven.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/scene.hpp"

using impact::Event;
using impact::EventDrivenParams;
using impact::EventKind;
using impact::Model;
using impact::State;

namespace {

constexpr double kG = 9.80665;
constexpr double kPi = std::numbers::pi;

Model expression_model(const std::string& expression, std::optional<double> cor) {
  Model m;
  m.cor = cor;
  m.expression = expression;
  return m;
}

struct Sampled {
  std::vector<State> states;
  std::vector<Event> events;
};

// Runs a method on the grid, keeping every sample and every event.
Sampled sample(const Model& model, const impact::MethodParams& params, const State& initial,
               const impact::Grid& grid) {
  Sampled out;
  impact::AnyStepper stepper = impact::make_stepper(model, grid.h, params);
  std::visit(
      [&](auto& s) {
        if constexpr (requires { s.set_event_sink(impact::EventSink{}); })
          s.set_event_sink([&](const Event& e) { out.events.push_back(e); });
      },
      stepper);
  impact::simulate(
      stepper, initial, grid,
      [&](std::int64_t, const State& s, const impact::StepInfo&) { out.states.push_back(s); });
  return out;
}

}  // namespace

TEST_CASE("event_driven: a harmonic force as an expression agrees with exact to 1e-9",
          "[event_driven]") {
  // The vibrating table at Gamma = 1.5, e = 0.5. rk8pd at rtol 1e-12 and atol 1e-14 makes each
  // flight exact to ~1e-12 and each impact time to ~1e-12 / V; over 2 s (about 20 impacts, each
  // multiplying an error in the launch speed by at most ~e (1 + |f'| dt / V) ~ 1) 1e-9 holds with
  // a margin of 10 or more.
  Model harmonic;
  harmonic.f = -kG;
  harmonic.cor = 0.5;
  harmonic.harmonic = impact::Harmonic{1.5 * kG, 20 * kPi, 0.0};
  const Model expression =
      expression_model("-9.80665 + 1.5 * 9.80665 * sin(20 * pi * t)", harmonic.cor);
  const State initial{0.05, 0.5};
  const impact::Grid grid{1e-3, 2000};
  const Sampled exact = sample(harmonic, impact::ExactParams{}, initial, grid);
  const Sampled ode = sample(expression, EventDrivenParams{}, initial, grid);
  // The tail of a chatter (impacts below ~1e-8 m/s, then the stick) is resolved at the level of
  // each method's rounding and tolerance, so one may end it an impact sooner: the impacts above
  // 1e-6 m/s and the lift-offs are compared one to one.
  const auto resolved = [](const std::vector<Event>& events) {
    std::vector<Event> kept;
    for (const Event& e : events)
      if (e.kind == EventKind::lift || (e.kind == EventKind::impact && -e.v_before > 1e-6))
        kept.push_back(e);
    return kept;
  };
  const std::vector<Event> a = resolved(exact.events), b = resolved(ode.events);
  REQUIRE(a.size() >= 10);
  REQUIRE(b.size() == a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    CHECK(b[k].kind == a[k].kind);
    CHECK(b[k].t == Approx(a[k].t).margin(1e-9));
    CHECK(b[k].v_before == Approx(a[k].v_before).margin(1e-9));
  }
  double worst = 0;
  for (std::size_t l = 0; l < exact.states.size(); ++l)
    worst = std::fmax(worst, std::fmax(std::fabs(ode.states[l].u - exact.states[l].u),
                                       std::fabs(ode.states[l].v - exact.states[l].v)));
  CHECK(worst < 1e-9);
}

TEST_CASE("event_driven: a constant expression agrees with the closed form", "[event_driven]") {
  // Gravity with COR 0.75 up to just before the Zeno time: the ODE flights are polynomials rk8pd
  // integrates exactly, so only the impact times' rounding (~1e-15) and the tolerances matter.
  const Model expression = expression_model("-9.80665", 0.75);
  Model constant;
  constant.f = -kG;
  constant.cor = 0.75;
  const State initial{5.0, -1.0};
  const impact::ExactSolution closed(constant, initial);
  const impact::Grid grid{1e-3, 6900};  // t_inf = 7.0026 s
  const Sampled ode = sample(expression, EventDrivenParams{}, initial, grid);
  for (std::size_t l = 0; l < ode.states.size(); ++l) {
    const State ref = closed.at(grid.t(static_cast<std::int64_t>(l)));
    REQUIRE(ode.states[l].u == Approx(ref.u).margin(1e-10));
    REQUIRE(ode.states[l].v == Approx(ref.v).margin(1e-10));
  }
}

TEST_CASE("event_driven: a grazing impact between two samples is found", "[event_driven]") {
  // As in test_exact_forcing: f = sin t, v0 = -1/2, the gap's minimum at pi/3 lies 1e-10 below the
  // floor, a dip 3e-5 wide between the samples 1.04 and 1.05.
  const double t_m = kPi / 3, depth = 1e-10;
  const State initial{std::sin(t_m) - t_m / 2 - depth, -0.5};
  const Sampled ode = sample(expression_model("sin(t)", 1.0), EventDrivenParams{}, initial,
                             impact::Grid{0.01, 150});
  REQUIRE(ode.events.size() >= 1);
  CHECK(ode.events[0].kind == EventKind::impact);
  // Entry into the dip, to the cubic term (< depth) and the gap's rounding over the slope.
  const double slope = std::sqrt(2 * depth * std::sin(t_m));
  CHECK(ode.events[0].t ==
        Approx(t_m - std::sqrt(2 * depth / std::sin(t_m))).margin(depth + 1e-13 / slope));
}

TEST_CASE("event_driven: lift-off where the expression crosses 0 upward", "[event_driven]") {
  // f = -1 + 2 sin t: resting from t = 0, lift at pi/6 (Brent on f, to a few ulp).
  const Sampled ode = sample(expression_model("-1 + 2 * sin(t)", 0.0), EventDrivenParams{},
                             {0.0, 0.0}, impact::Grid{0.01, 1000});
  REQUIRE(ode.events.size() >= 2);
  CHECK(ode.events[0].kind == EventKind::stick);
  CHECK(ode.events[1].kind == EventKind::lift);
  CHECK(ode.events[1].t == Approx(kPi / 6).margin(1e-14));
}

TEST_CASE("event_driven: a particle at rest on the floor leaves it where f turns positive",
          "[event_driven][regression]") {
  // Each used to stop with "the solve did not converge after 0 iterations": f = 0 exactly at the
  // start and rising (t, sin t) was taken for a force that holds the particle, which then took
  // off again at once; f > 0 only until before the first sample (1e-300 - t) was never certified.
  const impact::Grid grid{1e-3, 2000};
  const Sampled t = sample(expression_model("t", std::nullopt), EventDrivenParams{}, {0, 0}, grid);
  // Free flight from rest: u = t^3/6, v = t^2/2, integrated by rk8pd to its tolerance.
  CHECK(t.states.back().u == Approx(4.0 / 3).epsilon(1e-12));
  CHECK(t.states.back().v == Approx(2.0).epsilon(1e-12));
  const Sampled sine =
      sample(expression_model("sin(t)", std::nullopt), EventDrivenParams{}, {0, 0}, grid);
  CHECK(sine.states.back().u == Approx(2 - std::sin(2.0)).epsilon(1e-12));
  CHECK(sine.states.back().v == Approx(1 - std::cos(2.0)).epsilon(1e-12));
  // Positive for 1e-300 s, then pulling down: the particle stays.
  const Sampled stays =
      sample(expression_model("1e-300 - t", std::nullopt), EventDrivenParams{}, {0, 0}, grid);
  CHECK(stays.states.back().u == 0.0);
  CHECK(stays.states.back().v == 0.0);
  // A plastic landing where f is 1e-7 for another 1e-8 s: an impact of 7e-16 m/s later it rests
  // until f crosses 0 upward at (pi + 0.01) / 10, as exact finds for the same force as a harmonic.
  Model harmonic;
  harmonic.f = 1e-7;
  harmonic.cor = 0.0;
  harmonic.harmonic = impact::Harmonic{1.0, 10.0, kPi - 0.01};
  const State landing{0.001, -1.0};
  const Sampled ode =
      sample(expression_model("1e-7 - sin(10*t - 0.01)", 0.0), EventDrivenParams{}, landing, grid);
  const Sampled exact = sample(harmonic, impact::ExactParams{}, landing, grid);
  REQUIRE(ode.events.size() == exact.events.size());
  for (std::size_t k = 0; k < ode.events.size(); ++k) {
    CHECK(ode.events[k].kind == exact.events[k].kind);
    CHECK(ode.events[k].t == Approx(exact.events[k].t).margin(1e-12));
  }
  CHECK(exact.events.back().kind == EventKind::lift);
  CHECK(exact.events.back().t == Approx((kPi + 0.01) / 10).margin(1e-12));
  for (std::size_t l = 0; l < ode.states.size(); ++l)
    REQUIRE(ode.states[l].u == Approx(exact.states[l].u).margin(1e-12));
  // The table at rest with phase asin(g/A), f(0) = 0 rising, as a harmonic force: as exact.
  Model table;
  table.f = -kG;
  table.cor = 0.5;
  table.harmonic = impact::Harmonic{14.71, 62.831853, std::asin(kG / 14.71)};
  const impact::Grid fine{1e-4, 20000};
  const Sampled table_ode = sample(table, EventDrivenParams{}, {0, 0}, fine);
  const Sampled table_exact = sample(table, impact::ExactParams{}, {0, 0}, fine);
  for (std::size_t l = 0; l < table_ode.states.size(); ++l)
    REQUIRE(table_ode.states[l].u == Approx(table_exact.states[l].u).margin(1e-9));
}

TEST_CASE("event_driven: a force defined up to T only is evaluated up to T",
          "[event_driven][regression]") {
  // sqrt(2 - t) - 9.8 is NaN past t = 2: the lift-off scan looked 5 s ahead of a resting particle,
  // and an ODE step of a flight could end past T, both failing the run (also as the reference of
  // direct --against exact). A scene's stepper and the error reference stop at T.
  for (const double v0 : {0.0, 10.0}) {  // resting all along; in flight at T
    INFO("v0 = " << v0);
    const impact::Scene scene =
        impact::make_scene(expression_model("sqrt(2 - t) - 9.8", {}), {v0 == 0 ? 0.0 : 1.0, v0},
                           2.0, 1e-3, EventDrivenParams{});
    impact::AnyStepper stepper = impact::make_stepper(scene);
    State end;
    CHECK_NOTHROW(
        impact::simulate(stepper, scene.initial, scene.grid,
                         [&](std::int64_t, const State& s, const impact::StepInfo&) { end = s; }));
    if (v0 > 0)  // u(2) = 1 + 2 v0 - 9.8 * 2^2 / 2 + the integral of (2 - s)^(3/2) over [0, 2]
      CHECK(end.u == Approx(1 + 20 - 19.6 + 0.4 * std::pow(2, 2.5)).epsilon(1e-10));
    impact::AnyStepper direct = impact::make_stepper(scene.model, 1e-3, impact::DirectParams{});
    CHECK_NOTHROW(impact::measure_errors(direct, scene.model, scene.initial, scene.grid));
  }
}

TEST_CASE(
    "event_driven: a force faster than its lift-off scan lifts the particle at every crossing",
    "[event_driven][regression]") {
  // The table at 1 kHz (f = -g + 14.71 sin(6283.1853 t)): its period, 1 ms, is shorter than the
  // scan's spacing (max_step / 8 = 1.25 ms), and Brent between two samples found the last of
  // three crossings: event_driven lifted at 929 of exact's 1858 lift-offs, its E off by 2x. Now
  // the events are exact's, the states within 1e-12 (measured 9e-15).
  Model harmonic;
  harmonic.f = -kG;
  harmonic.cor = 0.5;
  harmonic.harmonic = impact::Harmonic{14.71, 6283.1853, 0.0};
  const Model expression = expression_model("-9.80665 + 14.71 * sin(6283.1853 * t)", 0.5);
  const impact::Grid grid{1e-4, 20000};
  const Sampled exact = sample(harmonic, impact::ExactParams{}, {0.01, 0.0}, grid);
  const Sampled ode = sample(expression, EventDrivenParams{}, {0.01, 0.0}, grid);
  const auto lifts = [](const Sampled& s) {
    return std::count_if(s.events.begin(), s.events.end(),
                         [](const Event& e) { return e.kind == EventKind::lift; });
  };
  CHECK(lifts(exact) == 1858);
  CHECK(lifts(ode) == lifts(exact));
  for (std::size_t l = 0; l < ode.states.size(); ++l) {
    REQUIRE(ode.states[l].u == Approx(exact.states[l].u).margin(1e-12));
    REQUIRE(ode.states[l].v == Approx(exact.states[l].v).margin(1e-9));
  }
}

TEST_CASE("event_driven: a chatter ends in sticking within the window", "[event_driven]") {
  const Model expression = expression_model("-9.80665", 0.5);
  Model constant;
  constant.f = -kG;
  constant.cor = 0.5;
  const double t_inf = *impact::ExactSolution(constant, {1.0, 0.0}).rest_time();
  impact::ExactMarch<impact::OdeLaw> track(impact::OdeLaw(expression, {}), expression, {1.0, 0.0},
                                           0.0);
  std::vector<Event> events;
  track.set_event_sink([&](const Event& e) { events.push_back(e); });
  double impulse = 0;
  for (int l = 1; l <= 3000; ++l) track.advance(l * 1e-3, impulse);
  REQUIRE(events.back().kind == EventKind::stick);
  REQUIRE(track.chatter_window() > 0);
  // The stick comes before t_inf by at most the window, up to the ODE's tolerance in the times.
  CHECK(events.back().t <= t_inf + 1e-10);
  CHECK(t_inf - events.back().t <= track.chatter_window() + 1e-10);
  // The impulse identity: resting from the stick on, N = -f, so the total impulse over [0, 3] is
  // v(3) - v(0) - integral of f = 0 - 0 + 3 g.
  CHECK(impulse == Approx(3 * kG).epsilon(1e-10));
}

TEST_CASE("event_driven: measure_errors takes it as the reference for an expression",
          "[event_driven]") {
  // direct on the table at Gamma = 1.5 as an expression, h = 1e-3: its error against the ODE
  // reference must equal its error against exact for the same force written as harmonic, to the
  // references' agreement (1e-9 above) and the schemes' step means (GL16 against closed form).
  const std::string text = "-9.80665 + 1.5 * 9.80665 * sin(20 * pi * t)";
  Model expression = expression_model(text, 0.5);
  Model harmonic;
  harmonic.f = -kG;
  harmonic.cor = 0.5;
  harmonic.harmonic = impact::Harmonic{1.5 * kG, 20 * kPi, 0.0};
  const State initial{0.05, 0.5};
  const impact::Grid grid{1e-3, 1000};
  impact::AnyStepper a = impact::make_stepper(expression, grid.h, impact::DirectParams{});
  impact::AnyStepper b = impact::make_stepper(harmonic, grid.h, impact::DirectParams{});
  const impact::ErrorNorms ea = impact::measure_errors(a, expression, initial, grid);
  const impact::ErrorNorms eb = impact::measure_errors(b, harmonic, initial, grid);
  CHECK(ea.sup_u > 0);
  CHECK(ea.sup_u == Approx(eb.sup_u).epsilon(1e-6));
  CHECK(ea.first_impact == Approx(eb.first_impact).margin(1e-9));
}

TEST_CASE("event_driven: parameters out of range are refused", "[event_driven]") {
  const Model m = expression_model("-9.8", std::nullopt);
  CHECK_THROWS_AS(impact::EventDriven(m, 1e-3, EventDrivenParams{0.0, 1e-14, 0.01}),
                  std::invalid_argument);
  CHECK_THROWS_AS(impact::EventDriven(m, 1e-3, EventDrivenParams{1e-12, -1.0, 0.01}),
                  std::invalid_argument);
  CHECK_THROWS_AS(impact::EventDriven(m, 1e-3, EventDrivenParams{1e-12, 1e-14, 0.0}),
                  std::invalid_argument);
  CHECK_THROWS_AS(impact::EventDriven(expression_model("sin(", std::nullopt), 1e-3, {}),
                  std::invalid_argument);
}
