// A bonded run through the library, kept step by step (its states with beta and D, and its
// events), and the checks on it that every bonded method must pass. Shared by test_bonding.cpp and
// test_bonding_steppers.cpp.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

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

}  // namespace impact::testing
