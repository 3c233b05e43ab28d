// `impact run --events FILE`: the events a time-stepper's steps show (step_events.hpp) and their
// CSV, for a bouncing ball whose impact times are known in closed form and for a particle resting
// on the floor that a harmonic force lifts.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/forces/force.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/step_events.hpp"

using Catch::Contains;
using impact::Event;
using impact::EventKind;
using namespace impact::testing;

namespace {

constexpr double kG = 9.80665;

// The impact times of a ball dropped from rest at height H under f = -g with restitution e:
// t_1 = sqrt(2 H / g), and each flight after impact k lasts 2 e^k V / g, V = sqrt(2 g H).
std::vector<double> bouncing_ball_impacts(double H, double e, int count) {
  const double V = std::sqrt(2 * kG * H);
  std::vector<double> t{V / kG};
  for (int k = 1; k < count; ++k) t.push_back(t.back() + 2 * std::pow(e, k) * V / kG);
  return t;
}

// A minimal inelastic time-stepper with the step-mean force: symplectic Euler, and a step that
// would end below the floor ends on it at rest. Its contact impulse is what the step removes.
class InelasticEuler {
 public:
  InelasticEuler(const impact::Model& model, double h) : force_(model), h_(h) {}
  void initialize(const impact::State&, std::int64_t) {}
  impact::StepInfo do_step(impact::State& s, std::int64_t l) {
    const double f = force_.step_mean(static_cast<double>(l) * h_, h_);
    impact::State next{s.u + h_ * (s.v + h_ * f), s.v + h_ * f};
    impact::StepInfo info;
    if (next.u < force_.model().phi) {
      info.contact_force = -next.v / h_;
      next = {force_.model().phi, 0.0};
    }
    s = next;
    return info;
  }

 private:
  impact::ForceFunction force_;
  double h_;
};

}  // namespace

TEST_CASE("events: a time-stepper's impacts, stick and lift under a harmonic force", "[events]") {
  // f(t) = -g + 2 g sin(2 pi t): at rest on the floor from t = 0 until f turns positive at
  // t* = 1/12 (sin = 1/2), then a flight that lands again; with an inelastic floor, a stick.
  impact::Model model;
  model.f = -kG;
  model.harmonic = impact::Harmonic{2 * kG, 2 * std::numbers::pi, 0.0};
  const double h = 1e-4;
  std::vector<Event> events;
  impact::StepEvents log(model, h, [&](const Event& e) { events.push_back(e); });
  InelasticEuler stepper(model, h);
  impact::simulate(stepper, impact::State{0.0, 0.0}, impact::Grid{h, 10000}, log);
  REQUIRE(events.size() >= 4);
  CHECK(events[0].kind == EventKind::stick);
  CHECK(events[0].t == 0.0);
  CHECK(events[1].kind == EventKind::lift);
  // The first free step starts at most one step after f's zero crossing: the step's mean force is
  // positive once the step starts past t* (and may be already before it).
  CHECK(std::fabs(events[1].t - 1.0 / 12) <= h);
  CHECK(events[2].kind == EventKind::impact);
  CHECK(events[2].v_before < 0);
  CHECK(events[2].v_after == 0.0);
  CHECK(events[3].kind == EventKind::stick);
  for (std::size_t i = 1; i < events.size(); ++i) CHECK(events[i].t >= events[i - 1].t);
}

TEST_CASE("events: --events for a bouncing ball gives the closed-form impact times", "[events]") {
  TempDir dir;
  const double H = 1.0, e = 0.5, h = 1e-4;
  const std::string scene =
      dir.write("ball.toml",
                "[initial]\nu0 = 1.0\nv0 = 0.0\n[floor]\ncor = 0.5\n[force]\nf = -9.80665\n"
                "[time]\nT = 2.0\nh = 0.0001\n[method]\nname = \"direct\"\n");
  const auto exact = bouncing_ball_impacts(H, e, 6);
  for (const std::string method : {"exact", "event_driven", "direct"}) {
    INFO(method);
    const Result r =
        dir.run("run ball.toml -q -o rows.csv --events events.csv --set method.name=" + method);
    REQUIRE(r.code == 0);
    const auto events = read_events(slurp(dir / "events.csv"));
    REQUIRE(events.size() >= exact.size());
    for (std::size_t k = 0; k < exact.size(); ++k) {
      INFO("impact " << k + 1);
      CHECK(events[k].kind == EventKind::impact);
      // exact and event_driven: to rounding. direct flies in closed form, so its first impact is
      // exact too; each later one is shifted by the scheme's impacts, each of which ends its
      // contact step on the floor at t_{l+1} (up to h late) with -e v^l (up to e h g off, so the
      // next flight is up to 2 e h off), and later impacts, at speeds e^k V, do not amplify these
      // shifts (measured: 0.99 h after the second impact, 3.98 h after the fifth).
      const double tolerance = method != "direct" || k == 0 ? 1e-12 : (1 + 2 * e) * k * h;
      CHECK(std::fabs(events[k].t - exact[k]) <= tolerance);
    }
    // The first impact's velocities: -V before, e V after (exact) or e |v^l| (direct).
    CHECK(events[0].v_before == Approx(-std::sqrt(2 * kG * H)).epsilon(1e-12));
  }
  CHECK(dir.entries() ==
        std::set<std::string>{"ball.toml", "rows.csv", "rows.csv.json", "events.csv"});
  (void)scene;
}

TEST_CASE("events: --events is written whole or not at all, and not over --out", "[events]") {
  TempDir dir;
  dir.write("s.toml", kShort);
  CHECK_FAILS_CLEANLY(dir, "run s.toml --events -", 2,
                      Contains("--events and --out lead to the same output"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o a.csv --events a.csv", 2,
                      Contains("--events and --out lead to the same output"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o a.csv --events s.toml", 2,
                      Contains("--events names the scene file itself"));
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o a.csv --events no/such/dir/e.csv", 2,
                      Contains("no/such/dir/e.csv"));
  // A run that fails leaves neither file.
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o a.csv --events e.csv --set time.h=1e-300", 2,
                      Contains("time.h"));
  // Events to standard output when the rows go to a file.
  const Result r = dir.run("run s.toml -q -o a.csv --events -");
  REQUIRE(r.code == 0);
  const auto events = read_events(r.out);
  REQUIRE(events.size() >= 1);
  CHECK(events[0].kind == EventKind::impact);
  CHECK(events[0].t == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("events: --events shows a particle at rest that a harmonic force lifts", "[events]") {
  // At rest on the floor under f(t) = -g + 2 g sin(2 pi t): it sticks from t = 0 while f <= 0 and
  // lifts where f turns positive, at t* = asin(1/2) / (2 pi) = 1/12 (measured: 0.0833 for the
  // time-steppers, 1/12 to 1e-17 for exact).
  TempDir dir;
  dir.write("lift.toml",
            "[initial]\nu0 = 0.0\nv0 = 0.0\n[floor]\ncor = 0.0\n"
            "[force]\nf = -9.80665\namplitude = 19.6133\nomega = 6.283185307179586\n"
            "[time]\nT = 2.0\nh = 1e-4\n[method]\nname = \"direct\"\n");
  for (const std::string method : {"direct", "moreau_jean", "exact", "event_driven"}) {
    INFO(method);
    const bool reference = method == "exact" || method == "event_driven";
    const Result r =
        dir.run("run lift.toml -q -o /dev/null --events - --set method.name=" + method);
    REQUIRE(r.code == 0);
    const auto events = read_events(r.out);
    REQUIRE(events.size() >= 5);
    CHECK(events[0].kind == EventKind::stick);
    CHECK(events[0].t == 0.0);
    CHECK(events[1].kind == EventKind::lift);
    // A time-stepper's first free step starts within a step of t* (its mean force turns positive
    // there); exact and event_driven find the zero of f itself, to their root solver's tolerance.
    CHECK(std::fabs(events[1].t - 1.0 / 12) <= (reference ? 1e-12 : 1e-4));
    // It lands at t = 0.8248 (exact) with COR 0, and rests until f turns positive again at 13/12.
    CHECK(events[2].kind == EventKind::impact);
    CHECK(std::fabs(events[2].t - 0.8248126) <= 1e-4);
    CHECK(events[2].v_after == 0.0);
    CHECK(events[3].kind == EventKind::stick);
    CHECK(events[4].kind == EventKind::lift);
    CHECK(std::fabs(events[4].t - 13.0 / 12) <= (reference ? 1e-12 : 1e-4));
  }
}
