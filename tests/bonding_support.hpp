// A bonded run through the library, kept step by step (its states with beta and D, and its
// events), and the checks on it that every bonded method must pass. Shared by test_bonding.cpp,
// test_bonding_steppers.cpp and test_bonding_fremond.cpp.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "cli_support.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "scene/read_scene.hpp"

namespace impact::testing {

struct Sampled {
  std::vector<StateWithInternal> states;
  std::vector<Event> events;
  Scene scene;
};

inline Sampled run_bonded(const std::string& text, const std::vector<std::string>& set = {}) {
  Sampled out;
  out.scene = parse_scene(text, "bonding.toml", set);
  AnyStepper stepper = make_stepper(out.scene);
  const EventSink sink = [&](const Event& e) { out.events.push_back(e); };
  // A time-stepper's events are read off its steps, as `impact run --events` reads them.
  const bool own_events = attach_event_sink(stepper, sink);
  // exact and event_driven date their own events; a time-stepper's come from its steps.
  const bool time_stepper = std::holds_alternative<DirectParams>(out.scene.method) ||
                            std::holds_alternative<MoreauJeanParams>(out.scene.method);
  REQUIRE(own_events != time_stepper);
  StepEvents step_events(out.scene.model, out.scene.grid.h, sink);
  simulate(stepper, out.scene.initial, out.scene.grid,
           [&](std::int64_t l, const auto& s, const StepInfo& info) {
             if constexpr (std::is_same_v<std::decay_t<decltype(s)>, StateWithInternal>)
               out.states.push_back(s);
             else
               FAIL("a bonded run steps the state with beta and D");
             if (!own_events) step_events(l, s, info);
           });
  return out;
}

// `impact sweep` of dir's s.toml over initial.v0 = 1, 2 with --summary `summary` (the channels a
// run writes after t,u,v, each with _T) against `impact run` at each v0: its last row less t, u
// and v is the sweep's row less v0, bit for bit.
inline void check_sweep_rows_are_last_rows(const TempDir& dir, const std::string& summary) {
  const Result sweep = dir.run("sweep s.toml --vary initial.v0=1,2 --summary " + summary + " -o -");
  INFO(sweep.err);
  REQUIRE(sweep.code == 0);
  for (const char* v0 : {"1", "2"}) {
    const Result run = dir.run(std::string("run s.toml -q -o - --set initial.v0=") + v0);
    REQUIRE(run.code == 0);
    const std::string last = run.out.substr(run.out.rfind('\n', run.out.size() - 2) + 1);
    std::string fields = last.substr(0, last.size() - 1);
    for (int k = 0; k < 3; ++k) fields = fields.substr(fields.find(',') + 1);
    CHECK_THAT(sweep.out, Catch::Contains("\n" + std::string(v0) + "," + fields + ",\n"));
  }
}

// `impact run` of the scene `plain` as it is, with [bonding] gamma = 0 and with beta0 = 0: the
// three write the same rows and events, byte for byte (a field that does not act is not run).
inline void check_idle_bonds_are_plain(const TempDir& dir, const std::string& plain) {
  dir.write("plain.toml", plain);
  dir.write("gamma0.toml", plain + "[bonding]\ngamma = 0.0\nL = 0.1\neps_a = 0.0\nbeta0 = 1.0\n");
  dir.write("beta0.toml", plain + "[bonding]\ngamma = 100.0\nL = 0.1\neps_a = 0.0\nbeta0 = 0.0\n");
  const Result a = dir.run("run plain.toml -o - --events plain.ev");
  const Result b = dir.run("run gamma0.toml -o - --events gamma0.ev");
  const Result c = dir.run("run beta0.toml -o - --events beta0.ev");
  INFO(a.err << b.err << c.err);
  REQUIRE(a.code == 0);
  CHECK(b.code == 0);
  CHECK(c.code == 0);
  CHECK(a.out == b.out);
  CHECK(a.out == c.out);
  CHECK(slurp(dir / "plain.ev") == slurp(dir / "gamma0.ev"));
  CHECK(slurp(dir / "plain.ev") == slurp(dir / "beta0.ev"));
}

inline std::vector<Event> impacts(const std::vector<Event>& events) {
  std::vector<Event> out;
  for (const Event& e : events)
    if (e.kind == EventKind::impact) out.push_back(e);
  return out;
}

// beta in [0, beta0] and never rising, D >= 0 and never falling, at every sample.
inline void check_bonds_monotone(const Sampled& run) {
  const double beta0 = run.scene.model.bonding->beta0;
  double beta = beta0, spent = 0;
  for (const StateWithInternal& s : run.states) {
    REQUIRE(s.finite());
    REQUIRE(s.z[kBondFraction] >= 0.0);
    REQUIRE(s.z[kBondFraction] <= beta);
    REQUIRE(s.z[kBondEnergy] >= spent);
    beta = s.z[kBondFraction];
    spent = s.z[kBondEnergy];
  }
}

// max over the samples of |E + D + (the impacts' losses so far) - E(0)|, E with the bonds'
// energy gamma beta^2 Phi(g) (model.hpp).
inline double energy_balance_error(const Sampled& run) {
  const double e0 = energy(run.scene.model, run.states.front());
  double worst = 0, lost = 0;
  std::size_t next = 0;
  for (std::size_t l = 0; l < run.states.size(); ++l) {
    const double t = run.scene.grid.t(static_cast<std::int64_t>(l));
    for (; next < run.events.size() && run.events[next].t <= t; ++next)
      if (run.events[next].kind == EventKind::impact)
        lost += 0.5 * (run.events[next].v_before * run.events[next].v_before -
                       run.events[next].v_after * run.events[next].v_after);
    const StateWithInternal& s = run.states[l];
    worst = std::fmax(worst, std::fabs(energy(run.scene.model, s) + s.z[kBondEnergy] + lost - e0));
  }
  return worst;
}

}  // namespace impact::testing
