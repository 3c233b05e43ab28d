// The events of a run, for `impact run --events FILE`: impacts, the start of a rest on the floor
// (stick) and its end (lift). The exact solutions know theirs; for a time-stepper an impact is a
// contact step (N^l > 0) after a free step. A bonded model (bonding.hpp) has three more, read off
// the states of any method (bond_events.hpp): debond (beta falls to bonding.debond_below),
// capture (a flight turns back towards the floor: its top) and escape (from here the particle
// never comes back, f = 0).
#pragma once

#include <array>
#include <functional>
#include <string_view>

#include "impact/model/model.hpp"

namespace impact {

enum class EventKind { impact, stick, lift, debond, capture, escape };

inline std::string_view event_name(EventKind kind) {
  switch (kind) {
    case EventKind::impact:
      return "impact";
    case EventKind::stick:
      return "stick";
    case EventKind::lift:
      return "lift";
    case EventKind::debond:
      return "debond";
    case EventKind::capture:
      return "capture";
    case EventKind::escape:
      return "escape";
  }
  return "impact";
}

// v_before and v_after are the velocities just before and just after the event (0 for stick, lift
// and capture; equal, the velocity at the event, for debond and escape).
// internal: the model's internal variables at the event (model.hpp; zero without them), for a
// bonded model beta and D.
struct Event {
  double t = 0.0;
  EventKind kind = EventKind::impact;
  double v_before = 0.0, v_after = 0.0;
  std::array<double, kMaxInternal> internal{};
};

// Where a solver that knows its events exactly reports them, in increasing t.
using EventSink = std::function<void(const Event&)>;

}  // namespace impact
