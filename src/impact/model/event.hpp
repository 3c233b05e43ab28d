// The events of a run, for `impact run --events FILE`: impacts, the start of a rest on the floor
// (stick) and its end (lift). The exact solutions know theirs; for a time-stepper an impact is a
// contact step (N^l > 0) after a free step.
#pragma once

#include <array>
#include <functional>
#include <string_view>

#include "impact/model/model.hpp"

namespace impact {

enum class EventKind { impact, stick, lift };

inline std::string_view event_name(EventKind kind) {
  switch (kind) {
    case EventKind::impact:
      return "impact";
    case EventKind::stick:
      return "stick";
    case EventKind::lift:
      return "lift";
  }
  return "impact";
}

// v_before and v_after are the velocities just before and just after the event (equal for stick
// and lift, 0 there).
// internal: the model's internal variables at the event (model.hpp; zero without them).
struct Event {
  double t = 0.0;
  EventKind kind = EventKind::impact;
  double v_before = 0.0, v_after = 0.0;
  std::array<double, kMaxInternal> internal{};
};

// Where a solver that knows its events exactly reports them, in increasing t.
using EventSink = std::function<void(const Event&)>;

}  // namespace impact
