// direct_located (src/impact/steppers/direct_located.hpp): (5-1) with each impact located inside
// its step. Its closed forms against explicit flights, its exactness under a constant force
// (Proposition L.1 of paper_notes/error_analysis.md), the impulse identity (4-9) with the body
// force, and its order under f(t).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "analysis/fit.hpp"
#include "impact/forces/force.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/direct_located.hpp"

using namespace impact;

namespace {

constexpr double kG = 9.80665;

// The bounces from the floor flown one by one (at most `limit` flights).
State bounces_one_by_one(double w, double r, double g, double e, int limit = 100000) {
  for (int k = 0; k < limit && w > 0; ++k) {
    const double flight = 2 * w / g;
    if (r < flight) return {r * (w - g * r / 2), w - g * r};
    r -= flight;
    w *= e;
  }
  return {0, 0};
}

double sup_error(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene);
  return measure_errors(stepper, scene.model, scene.initial, scene.grid).sup_u;
}

}  // namespace

TEST_CASE("direct_located: the floor arrival and the bounces in closed form", "[direct_located]") {
  // Falling from 1 m at 2 m/s under f = -10: g + v tau + f tau^2 / 2 = 0 at tau = 0.2899.
  const FloorArrival a = floor_arrival({1.0, -2.0}, -10.0);
  REQUIRE(a.found);
  CHECK(a.tau == Approx((-2.0 + std::sqrt(24.0)) / 10));
  CHECK(a.speed == Approx(std::sqrt(24.0)));
  // Rising first, f < 0: it comes back; f >= 0 and v >= 0: never; v < 0, f > 0 turning back: never.
  CHECK(floor_arrival({0.0, 1.0}, -10.0).tau == Approx(0.2));
  CHECK_FALSE(floor_arrival({1.0, 1.0}, 0.0).found);
  CHECK_FALSE(floor_arrival({1.0, -1.0}, 10.0).found);
  // At rest on the floor under gravity: the arrival is now, at speed 0.
  CHECK(floor_arrival({0.0, 0.0}, -10.0).tau == 0);
  for (double e : {0.0, 0.3, 0.75, 0.999, 1.0})
    for (double r : {0.05, 0.3, 1.0, 3.7, 20.0}) {
      INFO("e = " << e << ", r = " << r);
      const State closed = bounce_from_floor(2.0, r, -kG, e);
      const State looped = bounces_one_by_one(2.0, r, kG, e);
      CHECK(closed.u == Approx(looped.u).margin(1e-12));
      CHECK(closed.v == Approx(looped.v).margin(1e-12));
    }
  // Past the accumulation point 2 w / (g (1 - e)) the particle rests.
  const State rest = bounce_from_floor(2.0, 2 * 2.0 / (kG * 0.25) * 1.001, -kG, 0.75);
  CHECK(rest.u == 0);
  CHECK(rest.v == 0);
}

TEST_CASE(
    "direct_located: exact to rounding under a constant force, Zeno included (Proposition "
    "L.1)",
    "[direct_located]") {
  struct Case {
    double u0, v0, f;
    std::optional<double> cor;
    double T, h;
  };
  // Figure 4 with COR at a step longer than the last bounces; no COR (elastic); a step holding
  // the whole Zeno tail (h > t_inf - t_k for many k); f = 0; f > 0 pushing away.
  const Case cases[] = {{5, -1, -kG, 0.75, 10, 0.1},     {5, -1, -kG, {}, 10, 0.03},
                        {0.2, 0, -kG, 0.5, 2, 0.25},     {5.0123, -1, 0, 0.75, 10, 0.07},
                        {0.01, -1, kG, 0.6, 0.5, 0.013}, {3, 2, -kG, 0.999, 40, 0.01}};
  for (const Case& c : cases) {
    INFO("u0 = " << c.u0 << ", f = " << c.f << ", h = " << c.h);
    const Scene scene =
        make_scene(Model{0, c.f, c.cor}, State{c.u0, c.v0}, c.T, c.h, DirectLocatedParams{});
    CHECK(sup_error(scene) < 1e-12 * std::max(1.0, c.T * c.T));
  }
}

TEST_CASE("direct_located: h sum N^l = v^n - v^0 - int f, the impulse identity (4-9)",
          "[direct_located]") {
  const Scene scene =
      make_scene(Model{0, -kG, 0.75}, State{5, -1}, 10, 0.01, DirectLocatedParams{});
  AnyStepper stepper = make_stepper(scene);
  double impulse = 0;
  State last;
  simulate(stepper, scene.initial, scene.grid,
           [&](std::int64_t, const State& s, const StepInfo& info) {
             impulse += scene.grid.h * info.contact_force;
             last = s;
           });
  CHECK(impulse == Approx(last.v - scene.initial.v + kG * scene.grid.end()).margin(1e-11));
}

TEST_CASE("direct_located: second order under a harmonic force", "[direct_located]") {
  // The period-1 vibrating table of experiments/work_precision/table_period1.toml, T = 3 s.
  Model model{0, -kG, 0.5};
  model.harmonic = Harmonic{12.748645, 2 * M_PI, 0};
  const State start{0.63632579087044383, -5.9424654406835575};
  std::vector<double> hs, errors;
  for (double h : {4e-3, 2e-3, 1e-3, 5e-4}) {
    hs.push_back(h);
    errors.push_back(sup_error(make_scene(model, start, 3, h, DirectLocatedParams{})));
  }
  CHECK(fit_order(hs, errors).order > 1.9);
}

namespace {

// A fixed sequence of numbers in [0, 1) (splitmix64): the same cases on every platform.
class Uniform {
 public:
  double operator()(double lo, double hi) {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_ = 20130601;
};

// The exact flight under f + a sin(omega t + p) from (gap, v) at t0, at t.
State harmonic_flight(const Harmonic& hm, double f, const State& from, double t0, double t) {
  const double s = t - t0, w = hm.omega, c0 = std::cos(w * t0 + hm.phase);
  return {from.u + from.v * s + f * s * s / 2 -
              hm.amplitude / w *
                  ((std::sin(w * t + hm.phase) - std::sin(w * t0 + hm.phase)) / w - c0 * s),
          from.v + f * s - hm.amplitude / w * (std::cos(w * t + hm.phase) - c0)};
}

}  // namespace

TEST_CASE(
    "Proposition L.2: one located step from the exact state under f(t) misses it by at most "
    "F1 h^3 / 12 in position",
    "[direct_located][property]") {
  // paper_notes/error_analysis.md, Proposition L.2: a contact step from the exact state at t_l
  // with the impact at t* = t_l + x h, under f(t) = f + a sin(omega t + p) (F0 = |f| + |a|,
  // F1 = |a| omega): the position at t_{l+1} is off by at most F1 h^3 ((1 - x)^3 / 12 +
  // e (x^2/4 - x^3/6)) <= F1 h^3 / 12 at leading order, plus O(F0 F1 h^4 / V) (the sketch's
  // remainder; its terms, e F0 |tau_1 - tau*| h and the slope's 2 F0 h / V on the delay, add up to
  // about F0 F1 h^4 / (4 V): the check allows F0 F1 h^4 / V). The exact states before and after
  // the impact are the closed-form flights from (0, -V) and (0, e V) at t*, whose rounding (1e-15
  // m) is far below F1 h^3 (> 1e-9 m here). Measured over 2000 steps: the largest |error| is
  // 0.0818 F1 h^3 (near x = 0 or x = 1 with e near 1: the bound's 1/12 and e/12), and no step
  // exceeds F1 h^3 / 12.
  Uniform draw;
  double largest = 0;
  int steps = 0;
  for (int i = 0; steps < 2000 && i < 100000; ++i) {
    Model model;
    model.f = draw(-20, 5);
    model.harmonic = Harmonic{draw(1, 30), draw(0.5, 20), draw(0, 6.283)};
    model.cor = draw(0.1, 1);
    const double V = draw(1, 10), h = draw(5e-4, 1e-2), x = draw(0, 1), t_l = draw(0, 5);
    const double e = *model.cor, F0 = std::fabs(model.f) + model.harmonic->amplitude;
    const double F1 = model.harmonic->amplitude * model.harmonic->omega;
    if (F0 * h > 0.02 * V || model.harmonic->omega * h > 0.3 || e * V < 2 * F0 * h) continue;
    const double t_star = t_l + x * h;
    const State before = harmonic_flight(*model.harmonic, model.f, {0, -V}, t_star, t_l);
    const State after = harmonic_flight(*model.harmonic, model.f, {0, e * V}, t_star, t_l + h);
    if (!(before.u >= 0) || !(after.u > 0)) continue;
    const ForceFunction force(model);
    const double mean = force.integral(t_l, t_l + h) / h;
    const State free = harmonic_flight(*model.harmonic, model.f, before, t_l, t_l + h);
    const State located = located_step(before, free, t_l, h, mean, force, e);
    const double error = std::fabs(located.u - after.u);
    const double leading =
        F1 * h * h * h * ((1 - x) * (1 - x) * (1 - x) / 12 + e * (x * x / 4 - x * x * x / 6));
    INFO("case " << i << ": x " << x << ", e " << e << ", V " << V << ", h " << h << ", error "
                 << error << ", leading bound " << leading);
    CHECK(error <= leading + F0 * F1 * h * h * h * h / V);
    largest = std::fmax(largest, error / (F1 * h * h * h));
    ++steps;
  }
  REQUIRE(steps == 2000);
  INFO("largest error / (F1 h^3): " << largest);
  CHECK(largest <= 1.0 / 12);
}
