// A bonded run's own events (bond_events.hpp): debond, capture and escape, through run_scene as
// `impact run --events` and the sweep take them. What these tests protect: escape decided exactly
// past L (never_returns: the particle escapes if and only if v >= gamma beta^2 L / (2c)), the
// capture time and the debond time against their closed forms past L, the captures at the tops of
// the well's flights between exact's impacts, the events in increasing t, and the sweep's
// debond_time, capture_time and escape_time equal to the run's first events.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "impact/run/any_stepper.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

using namespace impact;

namespace {

struct Logged {
  std::vector<Event> events;
  PointSummary summary;
};

Logged run_logged(const std::string& text, const std::vector<std::string>& set = {}) {
  const Scene scene = parse_scene(text, "bond_events.toml", set);
  AnyStepper stepper = make_stepper(scene);
  Logged out;
  RunOutputs outputs;
  outputs.events = [&](const Event& e) { out.events.push_back(e); };
  outputs.summary = true;
  out.summary = *run_scene(scene, stepper, outputs).point;
  return out;
}

std::vector<Event> of_kind(const std::vector<Event>& events, EventKind kind) {
  std::vector<Event> out;
  for (const Event& e : events)
    if (e.kind == kind) out.push_back(e);
  return out;
}

// Past L with f = 0 (u0 = L, moving up): R = L, so beta = beta0 e^{-c t} with c = gamma L^2 -
// eps_a = 0.5 and the pull gamma beta^2 L = P e^{-2ct}, P = 10: v(t) = v0 - P (1 - e^{-2ct}) /
// (2c), which stops at t* = -ln(1 - 2c v0 / P) / (2c) if v0 < P / (2c) = 10, else never.
constexpr double kGamma = 100, kL = 0.1, kEpsA = 0.5, kC = kGamma * kL * kL - kEpsA,
                 kPull = kGamma * kL;
std::string past_l(const std::string& method, double v0, double T, double h) {
  return "[initial]\nu0 = 0.1\nv0 = " + std::to_string(v0) + "\n[time]\nT = " + std::to_string(T) +
         "\nh = " + std::to_string(h) + "\n[method]\nname = \"" + method +
         "\"\n[bonding]\ngamma = 100.0\nL = 0.1\neps_a = 0.5\nbeta0 = 1.0\n";
}

}  // namespace

TEST_CASE("bond events: past L, escape is decided exactly at v0 = gamma L / (2c)",
          "[bonding][events]") {
  const double threshold = kPull / (2 * kC);
  REQUIRE(threshold == 10.0);
  SECTION("v0 = 10.01 escapes at t = 0, and is never captured") {
    const Logged run = run_logged(past_l("event_driven", 10.01, 20.0, 1e-2));
    const auto escapes = of_kind(run.events, EventKind::escape);
    REQUIRE(escapes.size() == 1);
    CHECK(escapes[0].t == 0.0);
    CHECK(of_kind(run.events, EventKind::capture).empty());
    CHECK(run.summary.bonds.escape == 0.0);
    CHECK(std::isnan(run.summary.bonds.capture));
    // It never came back: the run ends moving up (v(T) -> v0 - 10 = 0.01 from above).
    CHECK(run.summary.final.v > 0.01);
  }
  SECTION("v0 = 9.99 is captured at t* = ln(1000) / (2c), never escapes") {
    const double v0 = 9.99, top = -std::log(1 - 2 * kC * v0 / kPull) / (2 * kC);
    const Logged run = run_logged(past_l("event_driven", v0, 8.0, 1e-3));
    CHECK(of_kind(run.events, EventKind::escape).empty());
    const auto captures = of_kind(run.events, EventKind::capture);
    REQUIRE(captures.size() == 1);
    // The capture is dated by v interpolated linearly in its step: the root's error is at most
    // h^2 max|v''| / (8 |v'|), here v' = -P e^{-2ct*} = -0.01, v'' = 2c * 0.01 = 0.01, h = 1e-3:
    // 1.25e-7; event_driven's own error (rtol 1e-12 on v ~ 10, ode_flight.hpp) adds at most
    // about 1e-11 / 0.01 = 1e-9.
    CHECK(std::fabs(captures[0].t - top) < 3e-7);
    CHECK(run.summary.bonds.capture == captures[0].t);
    CHECK(captures[0].v_before == 0.0);
    CHECK(captures[0].v_after == 0.0);
  }
}

TEST_CASE("bond events: debond is dated where beta = e^{-ct} meets bonding.debond_below",
          "[bonding][events]") {
  // Escaping past L (v0 = 10.01 > 10), beta = e^{-c t} for ever: it meets 0.01 at ln(100) / c.
  const double when = std::log(100.0) / kC;
  const Logged exact = run_logged(past_l("event_driven", 10.01, 10.0, 1e-3));
  const auto debonds = of_kind(exact.events, EventKind::debond);
  REQUIRE(debonds.size() == 1);
  // beta interpolated linearly: an error of at most h^2 c / 8 = 6e-8 (beta'' / beta' = -c).
  CHECK(std::fabs(debonds[0].t - when) < 1e-7);
  CHECK(debonds[0].internal[kBondFraction] == Approx(0.01).epsilon(1e-6));
  CHECK(exact.summary.bonds.debond == debonds[0].t);
  // direct's implicit Euler for beta, (1 + hc)^{-n}, meets it at h ln(100) / ln(1 + hc): first
  // order, ln(100)/c (1 + hc/2 + ...), so halving h halves the error.
  const auto error = [&](double h) {
    const Logged run = run_logged(past_l("direct", 10.01, 10.0, h));
    return std::fabs(run.summary.bonds.debond - when);
  };
  const double ratio = error(1e-3) / error(5e-4);
  CHECK(ratio > 1.9);
  CHECK(ratio < 2.1);
  SECTION("a beta0 at or below the threshold starts broken: no debond") {
    const Logged broken = run_logged(past_l("event_driven", 10.01, 1.0, 1e-3),
                                     {"bonding.beta0=0.01", "bonding.debond_below=0.01"});
    CHECK(of_kind(broken.events, EventKind::debond).empty());
    CHECK(std::isnan(broken.summary.bonds.debond));
  }
}

TEST_CASE("bond events: in the well with no damage a capture comes at the top of each flight",
          "[bonding][events][exact]") {
  // The acceptance scene: elastic, f = -9.81, gamma = 100, from the floor at v0 = 1: the flights
  // last T = 2 atan(10/9.81)/10 and turn at their middle.
  const double period = well_return_time(100.0, 9.81, 1.0), h = 1e-3;
  const Logged run = run_logged(
      "[initial]\nu0 = 0.0\nv0 = 1.0\n[force]\nf = -9.81\n[floor]\ncor = 1.0\n[time]\nT = 1.7\n"
      "h = 0.001\n[method]\nname = \"exact\"\n[bonding]\ngamma = 100.0\nL = 1e6\neps_a = 1e6\n"
      "beta0 = 1.0\n");
  const auto captures = of_kind(run.events, EventKind::capture);
  // The tops before T = 1.7: (k + 1/2) period <= 1.7, k = 0..10 (1.7 / period = 10.69).
  REQUIRE(captures.size() == static_cast<std::size_t>(std::floor(1.7 / period + 0.5)));
  // Linear interpolation of v: at most h^2 max|v''| / (8 min|v'|), |v''| = k |v| <= 100 and
  // |v'| = G + k g >= 9.81 in flight.
  const double bound = h * h * 100 / (8 * 9.81);
  for (std::size_t k = 0; k < captures.size(); ++k)
    CHECK(std::fabs(captures[k].t - (static_cast<double>(k) + 0.5) * period) < bound);
  // The method's impacts and the captures alternate, in increasing t.
  for (std::size_t i = 1; i < run.events.size(); ++i) {
    CHECK(run.events[i - 1].t <= run.events[i].t);
    CHECK((run.events[i - 1].kind == EventKind::capture) !=
          (run.events[i].kind == EventKind::capture));
  }
  CHECK(of_kind(run.events, EventKind::escape).empty());  // f < 0: every flight comes back
  CHECK(of_kind(run.events, EventKind::debond).empty());
  for (const Event& e : run.events) CHECK(e.internal[kBondFraction] == 1.0);
}
