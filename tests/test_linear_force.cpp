// A linear force of the state, force.linear = { k, c, u_eq } beside f and the harmonic part: the
// method exact (closed-form flights, linear_law.hpp) against event_driven on the same scene (which
// takes the force as the expression of the state it is), through the library on 20 random scenes
// and through `impact run --against exact`; and the scene keys: read, --set, --unset, --vary, the
// scene as run, and every bad input refused with exit 2 naming the key.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "check_near.hpp"
#include "cli_support.hpp"
#include "impact/forces/force.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

struct MethodRun {
  std::vector<Event> events;
  std::vector<State> samples;  // at t_1 .. t_n
  State end;
};

MethodRun run_method(const Model& model, const State& initial, double T, double h,
                     const MethodParams& method) {
  const Scene scene = make_scene(model, initial, T, h, method);
  AnyStepper stepper = make_stepper(scene);
  MethodRun run;
  RunOutputs outputs;
  outputs.events = [&](const Event& e) { run.events.push_back(e); };
  outputs.watch = [&](std::int64_t, const State& s, const StepInfo& info) {
    REQUIRE(info.converged);
    run.samples.push_back(s);
    run.end = s;
  };
  run_scene(scene, stepper, outputs);
  return run;
}

// The oscillator of the experiment impact_oscillator with a damper and gravity: a scene whose
// impacts never stop (COR 0.8), for the CLI.
const std::string kOscillatorScene =
    "[initial]\nu0 = 1.0\nv0 = 0.0\n[floor]\nphi = 0.5\ncor = 0.8\n"
    "[force]\nf = -0.2\namplitude = -1.0\nomega = 2.8\nphase = 1.5707963267948966\n"
    "linear = { k = 1.0, c = 0.05, u_eq = 0.0 }\n"
    "[time]\nT = 20.0\nh = 0.01\n[method]\nname = \"event_driven\"\n";

}  // namespace

TEST_CASE(
    "linear force: exact and event_driven agree to 1e-10 on 20 random scenes, damped and "
    "undamped",
    "[linear_force][exact][event_driven]") {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto in = [&](double a, double b) { return a + (b - a) * unit(rng); };
  double worst = 0.0;
  for (int i = 0; i < 20; ++i) {
    Model model;
    model.phi = in(-0.2, 0.2);
    model.f = in(-2, 0.5);
    model.linear = LinearSpring{in(0.3, 4), i % 2 ? in(0.05, 1.0) : 0.0, in(-0.5, 0.5)};
    if (i % 5 != 4)
      model.harmonic = Harmonic{in(-1.5, 1.5), in(0.5, 4), in(0, 2 * std::numbers::pi)};
    model.cor = in(0.5, 0.95);
    const State initial{model.phi + in(0.1, 1.5), in(-1, 1)};
    const double T = 8.0, h = 0.01;
    INFO("scene " << i << ": " << linear_as_expression(model).expression.text()
                  << ", phi = " << model.phi << ", COR " << *model.cor << ", u0 = " << initial.u
                  << ", v0 = " << initial.v);
    const MethodRun a = run_method(model, initial, T, h, ExactParams{});
    const MethodRun b = run_method(model, initial, T, h, EventDrivenParams{});
    // Every event up to the first stick: a chatter is cut off under a window each certifies in
    // its own way, inside which the two may differ by the cut-off's 1e-8 of the impact speed.
    double until = T;
    std::size_t n = 0;
    for (; n < a.events.size() && n < b.events.size(); ++n) {
      INFO("event " << n);
      REQUIRE(a.events[n].kind == b.events[n].kind);
      CHECK_NEAR(a.events[n].t, b.events[n].t, 1e-10);
      CHECK_NEAR(a.events[n].v_before, b.events[n].v_before, 1e-10);
      worst = std::fmax(worst, std::fabs(a.events[n].t - b.events[n].t));
      if (a.events[n].kind == EventKind::stick) {
        until = std::fmin(a.events[n].t, b.events[n].t);
        break;
      }
    }
    CHECK(n > 0);
    // The grid samples before it, and the state at T.
    REQUIRE(a.samples.size() == b.samples.size());
    for (std::size_t l = 0; l < a.samples.size() && static_cast<double>(l + 1) * h < until; ++l) {
      CHECK_NEAR(a.samples[l].u, b.samples[l].u, 1e-10);
      CHECK_NEAR(a.samples[l].v, b.samples[l].v, 1e-10);
      worst = std::fmax(worst, std::fabs(a.samples[l].u - b.samples[l].u));
    }
    CHECK_NEAR(a.end.u, b.end.u, 1e-10);
    CHECK_NEAR(a.end.v, b.end.v, 1e-10);
  }
  WARN("largest difference of exact and event_driven (event times, u at the samples): " << worst);
}

TEST_CASE("linear force: impact run --against exact measures event_driven within 1e-10",
          "[linear_force][cli]") {
  TempDir dir;
  dir.write("s.toml", kOscillatorScene);
  const Result r = dir.run("run s.toml -q -o run.csv --against exact");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string key = "sup|u - u_exact| = ";
  const auto at = r.err.find(key);
  REQUIRE(at != std::string::npos);
  const double sup_u = std::stod(r.err.substr(at + key.size()));
  CHECK(sup_u <= 1e-10);
  // The other methods that take a force of the state are checked against the same reference.
  for (const std::string method : {"direct", "moreau_jean"}) {
    const Result m = dir.run("run s.toml -q -o m.csv --against exact --set method.name=" + method);
    INFO(method << ": " << m.err);
    CHECK(m.code == 0);
    CHECK_THAT(m.err, Contains(key));
  }
}

TEST_CASE("linear force: the keys are read, set, unset, varied and written as run",
          "[linear_force][scene]") {
  TempDir dir;
  dir.write("s.toml", kOscillatorScene);
  const Scene scene = load_scene(dir / "s.toml");
  REQUIRE(scene.model.linear);
  CHECK(scene.model.linear->k == 1.0);
  CHECK(scene.model.linear->c == 0.05);
  const Scene set = load_scene(dir / "s.toml", {"force.linear.k=2.5", "force.linear.u_eq=-0.1"});
  CHECK(set.model.linear->k == 2.5);
  CHECK(set.model.linear->u_eq == -0.1);
  CHECK_FALSE(load_scene(dir / "s.toml", {}, {"force.linear"}).model.linear);
  // The scene as run has the table, and reruns to the same bytes.
  REQUIRE(dir.run("run s.toml -q -o run.csv --set force.linear.k=2").code == 0);
  const Result again = dir.run("sweep s.toml -q -o sweep.csv --vary force.linear.k=0.5,1.5");
  INFO(again.err);
  CHECK(again.code == 0);
  // A scene without the table gains it by --set.
  dir.write("plain.toml",
            "[initial]\nu0 = 1.0\nv0 = 0.0\n[force]\nf = -1.0\n[time]\nT = 1.0\nh = 0.01\n"
            "[method]\nname = \"exact\"\n");
  const Scene gained = load_scene(dir / "plain.toml", {"force.linear.c=0.5"});
  REQUIRE(gained.model.linear);
  CHECK(gained.model.linear->c == 0.5);
  CHECK(gained.model.linear->k == 0.0);
}

TEST_CASE("linear force: bad input is refused with exit 2, naming the key and what is allowed",
          "[linear_force][cli][hardening]") {
  TempDir dir;
  dir.write("s.toml", kOscillatorScene);
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set force.linear.k=inf", 2,
                      Contains("force.linear.k = inf") && Contains("finite"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set force.linear.c=nan", 2,
                      Contains("force.linear.c = nan"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set force.linear.kk=1", 2,
                      Contains("force.linear.kk") && Contains("k, c, u_eq"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set force.linear.k=stiff", 2,
                      Contains("force.linear.k") && Contains("must be a number"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set force.linear=3", 2,
                      Contains("force.linear = 3") && Contains("must be a table"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set 'force.linear={}'", 2,
                      Contains("force.linear = {}") && Contains("give k, c or u_eq"));
  CHECK_FAILS_CLEANLY(
      dir,
      "run s.toml -q -o o.csv --unset force.f --unset force.amplitude --unset force.omega "
      "--unset force.phase --set 'force.expression=\"-u\"'",
      2, Contains("force.expression = '-u'") && Contains("exclusive with force.linear"));
  for (const std::string method : {"fb_newton", "penalty", "direct_located"})
    CHECK_FAILS_CLEANLY(dir, "run s.toml -q -o o.csv --set method.name=" + method, 2,
                        Contains("method.name") && Contains("force.linear") &&
                            Contains("direct, moreau_jean, exact, event_driven take one"));
}
