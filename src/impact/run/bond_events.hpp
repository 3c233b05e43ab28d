// The events of a bonded model (bonding.hpp, event.hpp) for any method, read off its states at the
// grid times t_l in O(1) memory:
//  - debond: beta^{l+1} <= bonding.debond_below < beta^l, dated where beta, interpolated linearly
//    in the step, meets the threshold (a beta0 at or below it starts broken: no event);
//  - capture: a flight that rose (a state with gap > 0 and v > 0) turns, v^{l+1} <= 0: its top,
//    dated where v, interpolated linearly in the step, is 0 (an error of O(h^2) for a smooth
//    flight), once per rise;
//  - escape: with f = 0, the first t_l whose state the particle provably never comes back from
//    (never_returns, bonding.hpp: exact past L, sufficient short of it); after it, no capture or
//    escape. With another force none is reported (f < 0 brings every flight back; f > 0 or f(t)
//    is not decided).
// Every event carries beta and D, interpolated linearly at its time, as the other events of a
// bonded run do. The method's own events (impact, stick, lift) of a step are held and passed on
// with the bonds' events of that step in increasing t, so that the file stays in time order.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "impact/model/event.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The first time of each of the bonds' events in a run; NaN where there is none.
struct BondFates {
  double debond = std::numeric_limits<double>::quiet_NaN();
  double capture = std::numeric_limits<double>::quiet_NaN();
  double escape = std::numeric_limits<double>::quiet_NaN();
};

class BondEvents {
 public:
  // `sink` receives every event, the method's and the bonds', in increasing t; empty: the fates
  // alone are kept. Throws std::invalid_argument for a model that is not bonded.
  BondEvents(const Model& model, double h, EventSink sink);

  // An event of the method inside the step being taken, held until the step's end.
  void hold(const Event& e) { held_.push_back(e); }
  // The state at t_l (l = 0: the initial state): the bonds' events of the step that ended there,
  // passed on with those held.
  void operator()(std::int64_t l, const StateWithInternal& s);

  const BondFates& fates() const { return fates_; }

 private:
  void add(double t, EventKind kind, double v_before, double v_after, const StateWithInternal& s);
  Bonding bonds_;
  double phi_, h_;
  bool force_free_;  // f = 0 identically: escape is decided
  EventSink sink_;
  std::vector<Event> held_;
  StateWithInternal before_{};
  std::int64_t l_ = 0;
  bool rising_ = false, escaped_ = false, broken_ = false;
  BondFates fates_;
};

}  // namespace impact
