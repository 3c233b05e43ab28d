// Internal variables of the model (impact/model/model.hpp, internal.hpp): z' = g(t, u, v, z), read
// by the force, carried by the state (StateWithInternal) to every observer: rows, summary, errors
// against the reference and events. The test system has a closed form: a pull that decays,
// f = 5 - 15 z with z' = -z, z(0) = 1, so z = e^-t and f(t) = 5 - 15 e^-t: a particle dropped on
// the floor with a COR of 0.2 bounces, comes to rest while f < 0, and lifts off where f crosses 0,
// at t_L = ln 3 exactly; afterwards it flies from (0, 0) at t_L under f(t) in closed form.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "output_support.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

constexpr double kT = 2.0;
const State kDrop{0.2, 0.0};

Model decaying_pull() {
  Model model;
  model.cor = 0.2;
  model.expression = "5 - 15 * z";
  model.internal = {{"z", 1.0, "-z"}};
  return model;
}

// The flight after lift-off at t_L from (phi, 0) = (0, 0) under f = 5 - 15 e^-t.
State after_lift(double t, double t_lift) {
  const double s = t - t_lift, e0 = std::exp(-t_lift), e = std::exp(-t);
  return {2.5 * s * s + 15 * (e0 - e - e0 * s), 5 * s + 15 * (e - e0)};
}

struct Sampled {
  std::vector<StateWithInternal> states;
  std::vector<Event> events;
};

Sampled run_event_driven(const Model& model, double h) {
  const Scene scene = make_scene(model, kDrop, kT, h, EventDrivenParams{});
  AnyStepper stepper = make_stepper(scene);
  Sampled out;
  REQUIRE(attach_event_sink(stepper, [&](const Event& e) { out.events.push_back(e); }));
  simulate(stepper, scene.initial, scene.grid, [&](std::int64_t, const auto& s, const StepInfo&) {
    if constexpr (std::is_same_v<std::decay_t<decltype(s)>, StateWithInternal>)
      out.states.push_back(s);
    else
      out.states.push_back({s, {}});
  });
  return out;
}

const std::string kScene =
    "[initial]\nu0 = 0.2\nv0 = 0.0\n[floor]\ncor = 0.2\n[force]\nexpression = \"5 - 15 * z\"\n"
    "[time]\nT = 2.0\nh = 1e-3\n[method]\nname = \"event_driven\"\n"
    "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n";

}  // namespace

TEST_CASE("internal variables: event_driven follows z in flight and at rest, and lifts off at ln 3",
          "[internal][property]") {
  const double h = 1e-3, t_lift = std::log(3.0);
  const Sampled run = run_event_driven(decaying_pull(), h);
  REQUIRE(run.states.size() == 2001);
  // z = e^-t at every sample, in flight, at the impacts and at rest (rk8pd at rtol 1e-12).
  double z_error = 0, flight_error = 0;
  for (std::size_t l = 0; l < run.states.size(); ++l) {
    const double t = static_cast<double>(l) * h;
    z_error = std::fmax(z_error, std::fabs(run.states[l].z[0] - std::exp(-t)));
    if (t > t_lift) {
      const State exact = after_lift(t, t_lift);
      flight_error = std::fmax(flight_error, std::fabs(run.states[l].u - exact.u));
      flight_error = std::fmax(flight_error, std::fabs(run.states[l].v - exact.v));
    }
  }
  CHECK(z_error < 1e-10);
  CHECK(flight_error < 1e-8);
  // Impacts, a stick, then one lift where f(t, z(t)) = 5 - 15 z crosses 0: z = 1/3 there.
  REQUIRE(run.events.size() >= 3);
  const Event& lift = run.events.back();
  CHECK(lift.kind == EventKind::lift);
  CHECK(lift.t == Approx(t_lift).margin(1e-9));
  CHECK(lift.internal[0] == Approx(1.0 / 3).margin(1e-9));
  CHECK(run.events[run.events.size() - 2].kind == EventKind::stick);
  for (const Event& e : run.events) CHECK(e.internal[0] == Approx(std::exp(-e.t)).margin(1e-9));
}

TEST_CASE("internal variables: the same run as the force of t it stands for", "[internal]") {
  // f = 5 - 15 z with z = e^-t is f(t) = 5 - 15 e^-t: event_driven's two paths (z in its ODE and on
  // the floor, or an expression of t) agree to the ODE's tolerance.
  Model of_t;
  of_t.cor = 0.2;
  of_t.expression = "5 - 15 * exp(-t)";
  const Sampled with_z = run_event_driven(decaying_pull(), 1e-3),
                plain = run_event_driven(of_t, 1e-3);
  REQUIRE(with_z.states.size() == plain.states.size());
  double gap = 0;
  for (std::size_t l = 0; l < plain.states.size(); ++l)
    gap = std::fmax(gap, std::fabs(with_z.states[l].u - plain.states[l].u) +
                             std::fabs(with_z.states[l].v - plain.states[l].v));
  CHECK(gap < 1e-8);
  REQUIRE(with_z.events.size() == plain.events.size());
}

TEST_CASE("internal variables: direct and moreau_jean converge to event_driven at first order",
          "[internal][property]") {
  for (const MethodParams& params :
       {MethodParams{DirectParams{}}, MethodParams{MoreauJeanParams{}}}) {
    INFO(method_name(params));
    std::vector<ErrorNorms> errors;
    for (const double h : {4e-4, 2e-4, 1e-4}) {
      const Scene scene = make_scene(decaying_pull(), kDrop, kT, h, params);
      AnyStepper stepper = make_stepper(scene);
      RunOutputs outputs;
      outputs.against_exact = true;
      outputs.summary = true;
      const RunReport report = run_scene(scene, stepper, outputs);
      errors.push_back(*report.errors);
      // The summary carries z at T, near e^-T (explicit Euler: (1 - h)^(T/h)).
      CHECK(report.point->internal_final[0] == Approx(std::pow(1 - h, kT / h)).epsilon(1e-9));
    }
    // z is smooth (explicit Euler, order 1 pair by pair); u's error moves with where the impacts
    // fall on the grid (measured on an Intel Xeon family 6 model 167, pairwise: direct 0.75 then
    // 1.25, moreau_jean 1.22 then 1.59), so its order is taken over the whole range, h / 4
    // (direct 1.00, moreau_jean 1.40).
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const double z_order = std::log2(errors[k - 1].sup_internal / errors[k].sup_internal);
      INFO("h " << k << ": sup z " << errors[k].sup_internal << " order " << z_order);
      CHECK(z_order == Approx(1.0).margin(0.05));
    }
    const double u_order = std::log2(errors.front().sup_u / errors.back().sup_u) / 2;
    INFO("sup u " << errors.front().sup_u << " to " << errors.back().sup_u << ", order "
                  << u_order);
    CHECK(u_order > 0.9);
  }
}

TEST_CASE("internal variables: impact run writes z as the library computes it, past 2^16 steps",
          "[internal][cli]") {
  TempDir dir;
  dir.write("s.toml", kScene);
  for (const std::string method : {"direct", "moreau_jean", "event_driven"}) {
    INFO(method);
    const std::vector<std::string> sets = {"method.name=\"" + method + "\"", "time.h=2.5e-5"};
    Run loaded = load_run(dir / "s.toml", sets);
    std::vector<std::vector<double>> rows;
    const std::int64_t every = 7, last = loaded.scene.grid.steps;
    REQUIRE(last == 80000);
    simulate(loaded.stepper, loaded.scene.initial, loaded.scene.grid,
             [&](std::int64_t l, const auto& s, const StepInfo&) {
               if constexpr (std::is_same_v<std::decay_t<decltype(s)>, StateWithInternal>)
                 if (l % every == 0 || l == last)
                   rows.push_back({loaded.scene.grid.t(l), s.u, s.v, s.z[0]});
             });
    std::string args = "run s.toml -q -o rows.csv --events ev.csv --set output.every=7";
    for (const auto& s : sets) args += " --set " + quote(s);
    const Result r = dir.run(args);
    INFO("stderr: " << r.err);
    REQUIRE(r.code == 0);
    const Table csv = read_table(slurp(dir / "rows.csv"));
    CHECK(csv.columns == std::vector<std::string>{"t", "u", "v", "z"});
    CHECK(first_difference(csv, rows, {0, 1, 2, 3}) == "");
    const std::string events = slurp(dir / "ev.csv");
    CHECK(events.starts_with("t,kind,v_before,v_after,z\n"));
    CHECK_THAT(events, Contains(",lift,"));
  }
}

TEST_CASE("internal variables: bad [[internal]] tables and methods are refused with exit 2",
          "[internal][cli][regression]") {
  TempDir dir;
  const std::string head =
      "[initial]\nu0 = 0.2\nv0 = 0.0\n[force]\nexpression = \"-9.8 - z\"\n[time]\nT = 0.1\n"
      "h = 1e-3\n[method]\nname = \"event_driven\"\n";
  const auto refused = [&](const std::string& internal, const std::string& says) {
    dir.write("s.toml", head + internal);
    CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv", 2, Contains(says));
  };
  refused("[[internal]]\nname = \"t\"\ninitial = 0.0\nrate = \"1\"\n", "the name is taken");
  refused("[[internal]]\nname = \"z\"\ninitial = 0.0\nrate = \"1 +\"\n", "Unexpected end");
  refused("[[internal]]\nname = \"z\"\ninitial = 0.0\nrate = \"q\"\n", "Unexpected token \"q\"");
  refused("[[internal]]\nname = \"z\"\nrate = \"1\"\n", "needs initial");
  refused("[[internal]]\nname = \"z\"\ninitial = 0.0\nrate = \"1\"\nstiff = 1\n",
          "unknown key stiff");
  refused("[internal]\nname = \"z\"\ninitial = 0.0\nrate = \"1\"\n", "array of tables");
  refused("[[internal]]\nname = \"z\"\ninitial = nan\nrate = \"1\"\n", "finite");
  // A method that does not follow internal variables says so and names the ones that do.
  dir.write("s.toml", head + "[[internal]]\nname = \"z\"\ninitial = 0.0\nrate = \"1\"\n");
  CHECK_FAILS_CLEANLY(dir, "run s.toml -o out.csv --set method.name=exact", 2,
                      Contains("does not follow internal variables"));
}
