// The event track behind exact (a harmonic force) and event_driven (any f(t)), exact_march.hpp:
// an elastic impact keeps its speed to rounding however late it happens, so long runs do not
// drift; a run's work is bounded (method.max_events, max_ode_steps) and a track that stops says
// why.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cli_support.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"

using Catch::Matchers::Contains;
using namespace impact::testing;
using impact::Event;
using impact::EventKind;
using impact::Model;
using impact::State;

namespace {

struct Sampled {
  State end;
  std::vector<double> speeds;  // impact speeds, in order
};

Sampled run(const Model& model, const impact::MethodParams& method, const State& initial,
            const impact::Grid& grid) {
  Sampled out;
  impact::AnyStepper stepper = impact::make_stepper(model, grid.h, method);
  std::visit(
      [&](auto& s) {
        if constexpr (requires { s.set_event_sink(impact::EventSink{}); })
          s.set_event_sink([&](const Event& e) {
            if (e.kind == EventKind::impact) out.speeds.push_back(-e.v_before);
          });
      },
      stepper);
  impact::simulate(stepper, initial, grid,
                   [&](std::int64_t, const State& s, const impact::StepInfo&) { out.end = s; });
  return out;
}

// A constant force f as the track follows it: a harmonic part of amplitude 1e-300 (exact), or
// the expression "f" (event_driven).
Model tracked_constant(double f, bool expression) {
  Model m;
  if (expression) {
    m.expression = std::to_string(f);
    return m;
  }
  m.f = f;
  m.harmonic = impact::Harmonic{1e-300, 1.0, 0.0};
  return m;
}

}  // namespace

TEST_CASE("event track: an elastic impact keeps its speed to rounding, late or early",
          "[exact_march][regression]") {
  // u0 = 1 under f = -1e8: V = 14142 m/s, a flight of 2.8e-4 s, 7071 impacts in 2 s. The track
  // took each contact at the first double past the root, up to ulp(t) late, with the speed
  // |v| + |f| ulp(t): every impact gained (7070 of 7070), the last by 3.7e-9 relative. Rounding
  // alone moves a speed by a few ulp per impact, either way.
  const State initial{1.0, 0.0};
  const impact::Grid grid{1e-3, 2000};
  for (const bool expression : {false, true}) {
    INFO((expression ? "event_driven" : "exact"));
    const impact::MethodParams method =
        expression ? impact::MethodParams(impact::EventDrivenParams{}) : impact::ExactParams{};
    const Sampled s = run(tracked_constant(-1e8, expression), method, initial, grid);
    REQUIRE(s.speeds.size() == 7071);
    int rose = 0;
    double drift = 0;
    for (std::size_t k = 1; k < s.speeds.size(); ++k) {
      rose += s.speeds[k] > s.speeds[k - 1];
      drift = std::fmax(drift, std::fabs(s.speeds[k] / s.speeds[0] - 1));
    }
    CHECK(rose < 3500);
    // exact's flights are closed forms (measured drift 0); event_driven's rk8pd at rtol 1e-12
    // moves a launch speed by its tolerance at most (measured 5e-12).
    CHECK(drift < (expression ? 1e-10 : 1e-13));
  }
}

TEST_CASE("event track: a long elastic run matches the constant force's closed form",
          "[exact_march][regression]") {
  // The scene of the report: u0 = 1, f = -9.80665, T = 1e5 s, h = 0.5, 89283 impacts. exact gave
  // u_T = 0.7937, v_T = -2.011 against the closed form's 0.7217, -2.336 (an O(T^2) drift). Each
  // located impact now carries the rounding of its own flight (a few ulp of 0.9 s), not of t:
  // even added up without cancelling, 89283 x 4 x 1.1e-16 x 0.9 s = 3.5e-11 s of phase, i.e.
  // 3.5e-10 m/s in v (|f| x phase) and 1.6e-10 m in u (V x phase). Measured: 5e-11 and 2e-10.
  Model constant;
  constant.f = -9.80665;
  const State initial{1.0, 0.0};
  const impact::Grid grid{0.5, 200000};
  const impact::ExactSolution closed(constant, initial);
  const State want = closed.at(grid.end());
  const Sampled exact =
      run(tracked_constant(constant.f, false), impact::ExactParams{}, initial, grid);
  CHECK(std::fabs(exact.end.u - want.u) < 1e-9);
  CHECK(std::fabs(exact.end.v - want.v) < 1e-9);
  // event_driven (rk8pd between impacts) over 1108 impacts, T = 1e3: it was 5e-8 off in u, and is
  // now within its ODE tolerance (measured 3e-11).
  const impact::Grid shorter{0.5, 2000};
  const State want_shorter = closed.at(shorter.end());
  const Sampled ode =
      run(tracked_constant(constant.f, true), impact::EventDrivenParams{}, initial, shorter);
  CHECK(std::fabs(ode.end.u - want_shorter.u) < 1e-9);
  CHECK(std::fabs(ode.end.v - want_shorter.v) < 1e-9);
}

namespace {

// The vibrating table of the report: f = -g + 14.71 sin(omega t), u0 = 0.01, e = 0.5, h = 1e-4.
const std::string kTable =
    "[initial]\nu0 = 0.01\nv0 = 0.0\n[floor]\ncor = 0.5\n[force]\nf = -9.80665\namplitude = "
    "14.71\nomega = 62.831853\n[time]\nT = 2.0\nh = 1e-4\n[method]\nname = \"exact\"\n";

// The message of the NumericalError a scene's run stops with, or "no error".
std::string failure(const impact::Scene& scene) {
  impact::AnyStepper stepper = impact::make_stepper(scene);
  try {
    impact::simulate(stepper, scene.initial, scene.grid,
                     [](std::int64_t, const State&, const impact::StepInfo&) {});
  } catch (const impact::NumericalError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("event track: a run that passes more events than method.max_events stops saying so",
          "[exact_march][regression]") {
  // At omega = 1e9 the table throws the particle up and catches it every 6e-9 s once it has
  // landed (t = 0.045): 2.7e7 events by t = 0.16, 7.4 GB of --events by T = 0.25, and T = 2 ran
  // for about 30 min. With the automatic budget (1e6 + 1000 per grid step) it stops at t = 0.138.
  TempDir dir;
  dir.write("table.toml", kTable);
  CHECK_FAILS_CLEANLY(dir, "run table.toml -o out.csv --set force.omega=1e9 --set time.T=0.25", 1,
                      Contains("more than method.max_events allows (automatic: 1000000 + 1000 "
                               "per grid step, 2377000 here)") &&
                          Contains("raise method.max_events") && !Contains("did not converge"));
  // The key, for exact, and the same bound for event_driven (an expression bouncing every
  // 2.8e-4 s, 7071 impacts in 2 s).
  impact::Scene table = impact::parse_scene(
      kTable, "table.toml", {"force.omega=1e9", "time.T=0.25", "method.max_events=10000"});
  CHECK_THAT(failure(table), Contains("passed 10001 events") &&
                                 Contains("more than method.max_events allows (10000)"));
  Model bouncing;
  bouncing.expression = "-1e8";
  const impact::Scene ode = impact::make_scene(bouncing, {1.0, 0.0}, 2.0, 1e-3,
                                               impact::EventDrivenParams{.max_events = 1000});
  CHECK_THAT(failure(ode), Contains("passed 1001 events") && Contains("(1000)"));
  // Its ODE steps are bounded too: a force that varies every 1e-7 s.
  Model fast;
  fast.expression = "-9.8 + 1e4 * sin(1e7 * t)";
  const impact::Scene steps = impact::make_scene(fast, {1.0, 0.0}, 1.0, 1e-3,
                                                 impact::EventDrivenParams{.max_ode_steps = 10000});
  CHECK_THAT(failure(steps), Contains("rk8pd used up the run's budget of ODE steps (10000") &&
                                 Contains("raise method.max_ode_steps"));
  // Negative budgets are out of range.
  CHECK_THROWS_WITH(impact::parse_scene(kTable, "table.toml", {"method.max_events=-1"}),
                    Contains("method.max_events = -1"));
}

TEST_CASE("event track: a contact search that stalls says where it stalled",
          "[exact_march][regression]") {
  // amplitude = 1e300: each certified step near the floor is at most sqrt(2 gap / 1e300) s. It used
  // to read "the solve did not converge after 0 iterations".
  for (const char* method : {"exact", "event_driven"}) {
    INFO(method);
    const impact::Scene scene = impact::parse_scene(
        kTable, "table.toml", {"force.amplitude=1e300", std::string("method.name=") + method});
    const std::string message = failure(scene);
    CHECK_THAT(message, Contains("step 0 (from t = 0): the contact search stalled") &&
                            Contains("reached only t = ") && Contains("the bound on |f|") &&
                            !Contains("iterations"));
  }
}
