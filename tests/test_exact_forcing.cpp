// The event-driven exact solution for a harmonic force f(t) = f + A sin(omega t + phase)
// (exact_march.hpp, flight_search.hpp, ExactStepper): against the closed form of exact.hpp when
// A = 0, against hand-derived lift-off times, on grazing impacts that a sign check at sample times
// misses, on chatter, and against the work-energy identity of an elastic flight.
#include <gsl/gsl_integration.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/run/any_stepper.hpp"

using impact::ClosedFormMarch;
using impact::Event;
using impact::EventKind;
using impact::ExactSolution;
using impact::Harmonic;
using impact::Model;
using impact::State;

namespace {

constexpr double kG = 9.80665;
constexpr double kPi = std::numbers::pi;

Model harmonic_model(double f, double amplitude, double omega, double phase,
                     std::optional<double> cor) {
  Model m;
  m.f = f;
  m.cor = cor;
  m.harmonic = Harmonic{amplitude, omega, phase};
  return m;
}

std::vector<Event> events_until(ClosedFormMarch& track, double T, double h) {
  std::vector<Event> events;
  track.set_event_sink([&](const Event& e) { events.push_back(e); });
  double impulse = 0;
  for (double t = h; t <= T; t += h) track.advance(t, impulse);
  return events;
}

}  // namespace

TEST_CASE("exact forcing: amplitude 0 agrees with the closed form to rounding",
          "[exact][forcing]") {
  const Model with_zero = harmonic_model(-kG, 0.0, 3.0, 0.4, 0.8);
  Model constant = with_zero;
  constant.harmonic.reset();
  const State initial{2.0, 0.5};
  const ExactSolution closed(constant, initial);
  ClosedFormMarch track(with_zero, initial, 0.0);
  std::vector<Event> events;
  track.set_event_sink([&](const Event& e) { events.push_back(e); });
  // Up to just before the Zeno time: each impact time is a Brent root, exact to a few ulp of t
  // (~1e-15), and the launch speed carries |f| times that; over 30 bounces, whose errors are damped
  // by e each bounce, 1e-12 leaves a margin of 100 over that growth.
  const double T = *closed.rest_time() * 0.999;
  double impulse = 0;
  for (int i = 1; i <= 4000; ++i) {
    const double t = T * i / 4000;
    const State a = track.advance(t, impulse), b = closed.at(t);
    REQUIRE(a.u == Approx(b.u).margin(1e-12));
    REQUIRE(a.v == Approx(b.v).margin(1e-12));
  }
  REQUIRE(events.size() >= 20);
  for (std::size_t k = 0; k < events.size(); ++k) {
    CHECK(events[k].kind == EventKind::impact);
    CHECK(events[k].t ==
          Approx(*closed.impact_time(static_cast<std::int64_t>(k) + 1)).margin(1e-12));
    CHECK(-events[k].v_before ==
          Approx(*closed.impact_speed(static_cast<std::int64_t>(k) + 1)).margin(1e-12));
  }
}

TEST_CASE("exact forcing: a grazing impact between two samples is found", "[exact][forcing]") {
  // f(t) = sin t: from (u0, v0 = -1/2) at t = 0, v = v0 + 1 - cos t vanishes at t_m = pi/3, where
  // u = u0 - t_m/2 + t_m - sin t_m. u0 puts that minimum `depth` below the floor: the dip is
  // 2 sqrt(2 depth / sin t_m) wide (3e-5 for depth 1e-10), inside one sample step of 0.01.
  const Model model = harmonic_model(0.0, 1.0, 1.0, 0.0, 1.0);
  const double t_m = kPi / 3, h = 0.01;
  for (double depth : {1e-6, 1e-10, 1e-13}) {
    const double u0 = std::sin(t_m) - t_m / 2 - depth;
    ClosedFormMarch track(model, {u0, -0.5}, 0.0);
    bool sign_check_sees_it = false;
    std::vector<Event> events;
    track.set_event_sink([&](const Event& e) { events.push_back(e); });
    double impulse = 0;
    for (int l = 1; l <= 150; ++l) {
      const double t = l * h;
      const double free_gap = u0 - 0.5 * t + t - std::sin(t);
      sign_check_sees_it = sign_check_sees_it || free_gap <= 0;
      track.advance(t, impulse);
    }
    CHECK_FALSE(sign_check_sees_it);  // what a sign check at the samples would conclude
    REQUIRE(events.size() >= 1);
    CHECK(events[0].kind == EventKind::impact);
    // The entry into the dip: gap = depth - sin(t_m) (t - t_m)^2 / 2 = 0 before t_m, up to the
    // cubic term of the gap (cos(t_m) (t - t_m)^3 / 6, which moves the root by < depth) and the
    // rounding of the gap (~1e-16) divided by the slope sqrt(2 depth sin t_m) there.
    const double slope = std::sqrt(2 * depth * std::sin(t_m));
    const double entry = t_m - std::sqrt(2 * depth / std::sin(t_m));
    CHECK(events[0].t == Approx(entry).margin(depth + 1e-15 / slope));
    // Impact speed sin(t_m) (t_m - entry) = sqrt(2 depth sin t_m).
    CHECK(-events[0].v_before == Approx(slope).epsilon(1e-3));
  }
}

TEST_CASE("exact forcing: a resting particle lifts off where f crosses 0 upward",
          "[exact][forcing]") {
  // f = -1 + 2 sin t: on the floor from t = 0 (f(0) = -1), it lifts at sin t = 1/2, t = pi/6.
  const Model model = harmonic_model(-1.0, 2.0, 1.0, 0.0, 0.0);
  ClosedFormMarch track(model, {0.0, 0.0}, 0.0);
  const std::vector<Event> events = events_until(track, 10.0, 0.01);
  REQUIRE(events.size() >= 3);
  CHECK(events[0].kind == EventKind::stick);
  CHECK(events[0].t == 0.0);
  CHECK(events[1].kind == EventKind::lift);
  // asin(1/2) in closed form: to a few ulp of pi/6.
  CHECK(events[1].t == Approx(kPi / 6).margin(1e-15));
  // The plastic landing that follows, and the next lift a whole period later (from whichever stick
  // comes before it): pi/6 + 2 pi.
  CHECK(events[2].kind == EventKind::impact);
  CHECK(events[2].v_after == 0.0);
  bool lifted_again = false;
  for (std::size_t k = 2; k < events.size(); ++k)
    if (events[k].kind == EventKind::lift) {
      CHECK(events[k].t == Approx(kPi / 6 + 2 * kPi).margin(1e-14));
      lifted_again = true;
      break;
    }
  CHECK(lifted_again);
}

TEST_CASE("exact forcing: a chatter ends in sticking within the stated window",
          "[exact][forcing]") {
  SECTION("amplitude 0: the stick lies within W before the closed-form Zeno time") {
    Model model = harmonic_model(-kG, 0.0, 1.0, 0.0, 0.5);
    ClosedFormMarch track(model, {1.0, 0.0}, 0.0);
    const std::vector<Event> events = events_until(track, 3.0, 0.001);
    Model constant = model;
    constant.harmonic.reset();
    const double t_inf = *ExactSolution(constant, {1.0, 0.0}).rest_time();
    REQUIRE(events.back().kind == EventKind::stick);
    REQUIRE(track.chatter_window() > 0);
    CHECK(events.back().t <= t_inf + 1e-14);
    CHECK(t_inf - events.back().t <= track.chatter_window());
  }
  SECTION("harmonic: speeds below 1e-8 of the largest end in a stick, resting from then on") {
    // A table shaking at Gamma = 0.5 (it never lifts the particle off: f < 0 throughout).
    Model model = harmonic_model(-kG, 0.5 * kG, 2 * kPi, 0.0, 0.5);
    ClosedFormMarch track(model, {0.2, 0.0}, 0.0);
    const std::vector<Event> events = events_until(track, 3.0, 0.001);
    REQUIRE(events.size() >= 3);
    REQUIRE(events.back().kind == EventKind::stick);
    const Event& last = events[events.size() - 2];
    CHECK(last.v_after == 0.0);
    CHECK(-last.v_before < 1e-8 * -events[0].v_before);
    CHECK(track.chatter_window() > 0);
    CHECK(track.chatter_window() < 1e-7);  // 2 e V / (g_min (1 - rho)) with V < 1e-8 * 2
    double impulse = 0;
    const State rest = track.advance(3.0, impulse);
    CHECK(rest.u == 0.0);
    CHECK(rest.v == 0.0);
  }
}

TEST_CASE("exact forcing: an elastic flight changes v^2/2 by the work of f", "[exact][forcing]") {
  // Between impacts d(v^2/2)/dt = f(t) v, and an elastic impact keeps v^2: so v(T)^2/2 - v0^2/2 is
  // the integral of f v over [0, T], integrated here flight by flight with GSL's QAG (relative
  // 1e-12 per flight).
  const Model model = harmonic_model(-kG, 2.0 * kG, 2 * kPi, 0.3, 1.0);
  const State initial{0.3, 1.0};
  ClosedFormMarch track(model, initial, 0.0);
  std::vector<Event> events;
  track.set_event_sink([&](const Event& e) { events.push_back(e); });
  const double T = 12.0;
  double impulse = 0;
  const State end = track.advance(T, impulse);
  REQUIRE(events.size() >= 3);
  std::vector<double> starts{0.0};
  std::vector<State> anchors{initial};
  for (const Event& e : events) {
    REQUIRE(e.kind == EventKind::impact);
    CHECK(e.v_after == Approx(-e.v_before).epsilon(1e-15));
    starts.push_back(e.t);
    anchors.push_back({0.0, e.v_after});
  }
  starts.push_back(T);
  struct Power {
    impact::HarmonicFlight flight;
    Model model;
    static double at(double t, void* self) {
      const auto* p = static_cast<const Power*>(self);
      return impact::force_at(p->model, t) * p->flight.at(t).v;
    }
  };
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(200);
  double work = 0;
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    Power p{impact::HarmonicFlight(model, starts[k], anchors[k].u, anchors[k].v), model};
    gsl_function F{&Power::at, &p};
    double value = 0, error = 0;
    gsl_integration_qag(&F, starts[k], starts[k + 1], 0, 1e-12, 200, GSL_INTEG_GAUSS61, w, &value,
                        &error);
    work += value;
  }
  gsl_integration_workspace_free(w);
  // Impact times carry ~1e-15 relative rounding, speeds |f| times that: 1e-10 of the energy scale.
  CHECK(end.v * end.v / 2 - initial.v * initial.v / 2 == Approx(work).margin(1e-10));
}

TEST_CASE("exact forcing: ExactStepper samples a harmonic force as the track does",
          "[exact][forcing]") {
  // The stepper's in-flight samples rotate sin and cos from step to step (re-anchored every 32
  // samples); the track evaluates them directly. An ulp per rotation over 32 rotations, times
  // A/omega^2 ~ 0.5 in u and A/omega ~ 3 in v: 1e-13 is above that with a margin.
  const Model model = harmonic_model(-kG, 3.0 * kG, 2 * kPi, 0.0, 0.5);
  const State initial{0.0, 1.0};
  const impact::Grid grid{0.001, 20000};
  impact::AnyStepper stepper = impact::make_stepper(model, grid.h, impact::ExactParams{});
  int impacts = 0;
  std::get<impact::ExactStepper>(stepper).set_event_sink(
      [&](const Event& e) { impacts += e.kind == EventKind::impact; });
  ClosedFormMarch track(model, initial, 0.0);
  double impulse = 0, total = 0;
  State last = initial;
  impact::simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const auto& info) {
    if (l == 0) return;
    const State ref = track.advance(grid.t(l), impulse);
    REQUIRE(s.u == Approx(ref.u).margin(1e-13));
    REQUIRE(s.v == Approx(ref.v).margin(1e-13));
    total += info.contact_force * grid.h;
    last = s;
  });
  CHECK(impacts > 3);
  // The impulse identity (4-9) with f(t): h sum N^l = v^n - v^0 - integral of f over [0, T], each
  // step's impulse exact to rounding.
  const double drift =
      model.f * grid.end() + 3.0 * kG / (2 * kPi) * (1 - std::cos(2 * kPi * grid.end()));
  CHECK(total == Approx(last.v - initial.v - drift).margin(1e-11));
  CHECK(impulse == Approx(total).margin(1e-11));
}

TEST_CASE("exact forcing: a table's chatters decay to the cut-off, not to a rounding floor",
          "[exact][forcing]") {
  // e = 0.8 at Gamma = 1.05, 10 Hz, from rest: each table period the ball hops and chatters back
  // to rest. A gap evaluated through sin(omega t) at the absolute time carries ~1e-17 m of
  // rounding, under which impact speeds stall at ~2e-8 m/s, above the cut-off (1e-8 of ~0.05 m/s):
  // the chatter then never ends. Written from the flight's start, each chatter reaches the cut-off
  // in ~80 impacts (0.8^80 ~ 2e-8); 20 periods stay far below 10^4 impacts.
  const Model model = harmonic_model(-kG, 1.05 * kG, 20 * kPi, 0.0, 0.8);
  ClosedFormMarch track(model, {0.0, 0.0}, 0.0);
  const std::vector<Event> events = events_until(track, 2.0, 1e-3);
  long impacts = 0, sticks = 0;
  for (const Event& e : events) {
    impacts += e.kind == EventKind::impact;
    sticks += e.kind == EventKind::stick;
  }
  CHECK(track.converged());
  CHECK(sticks >= 19);
  CHECK(impacts < 10000);
}

TEST_CASE("exact forcing: a constant force's events come from the closed form",
          "[exact][forcing]") {
  // Figure 4 with COR 0.75: the impacts are ExactSolution's impact_time(k) and impact_speed(k) as
  // they are, down to the cut-off 1e-8 of the first speed (k - 1 <= log(1e-8) / log(0.75), i.e.
  // 65 impacts), then the stick at the Zeno time.
  Model model;
  model.f = -kG;
  model.cor = 0.75;
  const State initial{5.0, -1.0};
  const ExactSolution closed(model, initial);
  impact::AnyStepper stepper = impact::make_stepper(model, 1e-3, impact::ExactParams{});
  std::vector<Event> events;
  std::get<impact::ExactStepper>(stepper).set_event_sink(
      [&](const Event& e) { events.push_back(e); });
  impact::simulate(stepper, initial, impact::Grid{1e-3, 10000},
                   [](std::int64_t, const State&, const impact::StepInfo&) {});
  REQUIRE(events.size() == 66);
  for (std::int64_t k = 1; k <= 65; ++k) {
    const Event& e = events[static_cast<std::size_t>(k - 1)];
    CHECK(e.kind == EventKind::impact);
    CHECK(e.t == *closed.impact_time(k));
    CHECK(-e.v_before == *closed.impact_speed(k));
    CHECK(e.v_after == 0.75 * *closed.impact_speed(k));
  }
  CHECK(events.back().kind == EventKind::stick);
  CHECK(events.back().t == *closed.rest_time());
}

TEST_CASE("exact forcing: sequential sampling of a constant force is the closed form bit for bit",
          "[exact][forcing]") {
  // The stepper reuses the flight (and the rest) of the previous sample instead of inverting the
  // impact times at every grid point: the same formulas on the same numbers, so every sample and
  // every step's N^l equal at() and impulse() / h exactly, through the bounces, the Zeno time and
  // the rest of Figure 4 with COR 0.75 (and without COR).
  for (const std::optional<double> cor : {std::optional<double>(0.75), std::optional<double>()}) {
    Model model;
    model.f = -kG;
    model.cor = cor;
    const State initial{5.0, -1.0};
    const ExactSolution closed(model, initial);
    const impact::Grid grid{1e-3, 10000};
    impact::AnyStepper stepper = impact::make_stepper(model, grid.h, impact::ExactParams{});
    long mismatches = 0;
    impact::simulate(
        stepper, initial, grid, [&](std::int64_t l, const State& s, const impact::StepInfo& info) {
          const State ref = closed.at(grid.t(l));
          const double N = l > 0 ? closed.impulse(grid.t(l - 1), grid.t(l)) / grid.h : 0.0;
          mismatches += s.u != ref.u || s.v != ref.v || info.contact_force != N;
        });
    CHECK(mismatches == 0);
  }
}
