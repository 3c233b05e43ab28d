// Steps that repeat. Under a constant force a step of direct, fb_newton or moreau_jean is a
// function of the state it starts from alone (direct and fb_newton: of the state their last
// contact step ended in, from which the free flight is the closed form), so once a contact step
// ends in the same state, bit for bit, as an earlier one, every step after it repeats the steps
// after that one: a particle resting on the floor (COR 0.75: v = +-2^-1073, period 2) or in
// direct's chatter (period 2). A stepper that watches for it says so to simulate() (simulate.hpp,
// RepeatingSteps), which then takes one period and hands the rest of the run to the observer
// without stepping: the outputs are the same bits, at the cost of the observer alone.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "impact/model/model.hpp"

namespace impact {

// The longest period simulate() replays (it keeps one period of states).
inline constexpr std::int64_t kMaxRepeatPeriod = 8;

// Watches the states a stepper's contact steps end in, against those of its last two contact
// steps (a period-2 rest has one contact step per step, a chatter one or two per period).
class RepeatWatch {
 public:
  // Contact step l ended in s, the state that alone decides every step after it. Inlined and by
  // value, as everything on a step's path is (simulate.hpp, simulate()).
  [[gnu::always_inline]] void contact(std::int64_t l, State s) {
    const Key key{std::bit_cast<std::int64_t>(s.u), std::bit_cast<std::int64_t>(s.v), l};
    std::int64_t p = 0;
    if (key.a == last_[0].a && key.b == last_[0].b) p = l - last_[0].l;
    if (key.a == last_[1].a && key.b == last_[1].b && p == 0) p = l - last_[1].l;
    period_ = p <= kMaxRepeatPeriod ? p : 0;
    last_[1] = last_[0];
    last_[0] = key;
  }
  // p > 0 when the steps after the last contact step repeat with period p.
  std::int64_t period() const { return period_; }
  // The last contact step and the state it ended in.
  std::int64_t last_contact() const { return last_[0].l; }
  State last_state() const {
    return {std::bit_cast<double>(last_[0].a), std::bit_cast<double>(last_[0].b)};
  }
  // The run moved on by n steps without stepping (a multiple of the period).
  [[gnu::always_inline]] void skip(std::int64_t n) {
    last_[0].l += n;
    last_[1].l += n;
  }
  [[gnu::always_inline]] void reset() { *this = RepeatWatch(); }

 private:
  // Far enough back that l - kNone is no period; l never reaches it.
  static constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::min() / 4;
  struct Key {
    std::int64_t a = 0, b = 0, l = kNone;
  };
  Key last_[2];
  std::int64_t period_ = 0;
};

}  // namespace impact
