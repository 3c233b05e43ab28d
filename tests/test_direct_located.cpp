// direct_located (src/impact/direct_located.hpp): (5-1) with each impact located inside its step.
// Its closed forms against explicit flights, its exactness under a constant force (Proposition L.1
// of paper_notes/error_analysis.md), the impulse identity (4-9) with the body force, and its order
// under f(t).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "analysis/fit.hpp"
#include "impact/direct_located.hpp"
#include "impact/error_norms.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"

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
