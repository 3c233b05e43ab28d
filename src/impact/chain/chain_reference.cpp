#include "impact/chain/chain_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "impact/chain/chain_rest.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/flight_search.hpp"

namespace impact {

ChainReference::ChainReference(const Chain& chain, const ChainState& initial,
                               const ChainReferenceParams& params)
    : chain_(chain), e_(chain.cor.value_or(1.0)), t_end_(params.t_end) {
  check_chain(chain);
  check_chain_state(chain, initial);
  if (!(std::isfinite(t_end_) && t_end_ >= 0))
    throw std::invalid_argument("chain reference: t_end = " + std::to_string(t_end_) +
                                " is out of range: finite, >= 0");
  c1_ = chain.m1 / (chain.m1 + chain.m2);
  c2_ = chain.m2 / (chain.m1 + chain.m2);
  w_ = std::sqrt(chain.k * (1 / chain.m1 + 1 / chain.m2));
  ChainState gaps = initial;
  gaps.q = initial.q.array() - chain.phi;
  if (gaps.q(0) == 0 && gaps.v(0) == 0)
    settle(0.0, gaps);
  else
    segments_.push_back({0.0, gaps, false, 0.0});

  long budget = params.max_search_steps;
  while (segments_.back().resting ? next_lift(params, budget) : next_impact(params, budget)) {
  }
}

void ChainReference::settle(double t, const ChainState& s) {
  const double departure = chain_departure(chain_, s);
  if (departure > 0) {
    segments_.push_back({t, s, false, t + departure});
    return;
  }
  segments_.push_back({t, s, true, t});
  rests_.push_back({t});
}

bool ChainReference::next_lift(const ChainReferenceParams& params, long& budget) {
  const Segment& rest = segments_.back();
  const std::optional<Contact> lift = chain_lift(chain_, rest.t0, rest.s0, t_end_, budget);
  if (!lift) {
    if (budget <= 0)
      throw NumericalError("chain reference: the lift-off search took more than " +
                               std::to_string(params.max_search_steps) +
                               " certified steps before t = " + std::to_string(t_end_),
                           false);
    return false;  // at rest past t_end
  }
  // The first double with N <= 0: the flight starts there, N vanishing or pulling up.
  const double t = lift->t;
  if (t > t_end_) return false;
  const ChainState s = gaps_at(rest, t);
  const double departure = chain_departure(chain_, s);
  if (!(t > rest.t0 && departure > 0))
    throw NumericalError("chain reference: at t = " + std::to_string(t) +
                             " the lower mass is on the floor with zero speed and the contact "
                             "force and its rate both 0 (" +
                             describe(s) + " as gaps); which way it goes is not decided",
                         false);
  rests_.back().lift = t;
  segments_.push_back({t, s, false, t + departure});
  return true;
}

bool ChainReference::next_impact(const ChainReferenceParams& params, long& budget) {
  const Segment& flight = segments_.back();
  const double d0 = flight.s0.q(1) - flight.s0.q(0) - chain_.ell;
  const double rate0 = flight.s0.v(1) - flight.s0.v(0);
  const double amplitude = w_ > 0 ? std::hypot(d0, rate0 / w_) : 0.0;
  const double c2w2 = c2_ * w_ * w_;
  // |gap''| <= |g| + c2 w^2 max |d|: the bound that certifies the search's steps.
  const double bound = std::fabs(chain_.g) + c2w2 * amplitude;
  // The lower mass's gap and velocity, and its acceleration, for search_contact.
  struct LowerMass {
    const ChainReference& self;
    const Segment& flight;
    double g, c2w2, ell;
    State at(double t) const {
      const ChainState s = self.gaps_at(flight, t);
      return {s.q(0), s.v(0)};
    }
    double force(double t) const {
      const ChainState s = self.gaps_at(flight, t);
      return g + c2w2 * (s.q(1) - s.q(0) - ell);
    }
  } path{*this, flight, chain_.g, c2w2, chain_.ell};
  double certified = flight.certified, checked = flight.certified;
  const std::optional<Contact> contact =
      search_contact(path, bound, certified, checked, t_end_, budget);
  if (!contact) {
    if (budget <= 0)
      throw NumericalError(
          "chain reference: the impact search took more than " +
              std::to_string(params.max_search_steps) +
              " certified steps (a grazing flight?) before t = " + std::to_string(certified),
          false);
    return false;  // no impact before t_end
  }
  const double t = std::max(contact->t - contact->late, flight.certified);
  if (t > t_end_) return false;
  if (static_cast<std::int64_t>(impacts_.size()) >= params.max_impacts)
    throw NumericalError("chain reference: more than " + std::to_string(params.max_impacts) +
                             " impacts before t = " + std::to_string(t) +
                             " (an accumulation of impacts it could not cut off?)",
                         false);
  ChainState after = gaps_at(flight, t);
  after.q(0) = 0;  // on the floor
  const double speed = -std::fmin(contact->v, 0.0);
  fastest_ = std::fmax(fastest_, speed);
  after.v(0) = e_ * speed;  // Newton's law, (2-3)/Section 5.2
  // An accumulation cut off (see the header): this impact is plastic, the rest starts here.
  if (after.v(0) > 0 && e_ < 1 && speed < kChatterCutoff * fastest_ &&
      chain_chatter_window(chain_, e_, speed, after))
    after.v(0) = 0;
  impacts_.push_back({t, -speed, after.v(0)});
  if (after.v(0) > 0)
    segments_.push_back({t, after, false, t});
  else
    settle(t, after);
  return true;
}

ChainState ChainReference::gaps_at(const Segment& segment, double t) const {
  const double tau = t - segment.t0;
  const ChainState& s0 = segment.s0;
  if (segment.resting) return chain_rest_at(chain_, s0, tau);
  const double d0 = s0.q(1) - s0.q(0) - chain_.ell;
  const double rate0 = s0.v(1) - s0.v(0);
  // The stretch's departure from its linear motion, d(tau) - d0 - d'(0) tau, and its rate, in
  // forms without cancellation: cos x - 1 = -2 sin^2(x/2).
  double bend = 0, bend_rate = 0;
  if (w_ > 0) {
    const double x = w_ * tau, half = std::sin(x / 2), sine = std::sin(x);
    bend = -2 * d0 * half * half + rate0 * (sine - x) / w_;
    bend_rate = -d0 * w_ * sine - 2 * rate0 * half * half;
  }
  const double fall = chain_.g * tau * tau / 2;
  ChainState s;
  s.q(0) = s0.q(0) + s0.v(0) * tau + fall - c2_ * bend;
  s.q(1) = s0.q(1) + s0.v(1) * tau + fall + c1_ * bend;
  s.v(0) = s0.v(0) + chain_.g * tau - c2_ * bend_rate;
  s.v(1) = s0.v(1) + chain_.g * tau + c1_ * bend_rate;
  return s;
}

const ChainReference::Segment& ChainReference::segment_at(double t) const {
  const auto after = std::upper_bound(segments_.begin(), segments_.end(), t,
                                      [](double x, const Segment& f) { return x < f.t0; });
  return after == segments_.begin() ? segments_.front() : *(after - 1);
}

ChainState ChainReference::at(double t) const {
  const Segment& segment = segment_at(t);
  ChainState s = gaps_at(segment, std::max(t, segment.t0));
  s.q = s.q.array() + chain_.phi;
  return s;
}

double ChainReference::contact_force(double t) const {
  const Segment& segment = segment_at(t);
  if (!segment.resting) return 0;
  return chain_rest_force(chain_, gaps_at(segment, std::max(t, segment.t0)));
}

double ChainReference::impulse(double t0, double t1) const {
  const auto by_time = [](const ChainImpact& impact, double x) { return impact.t <= x; };
  const auto first = std::lower_bound(impacts_.begin(), impacts_.end(), t0, by_time);
  const auto last = std::lower_bound(impacts_.begin(), impacts_.end(), t1, by_time);
  double sum = 0;
  for (auto it = first; it < last; ++it) sum += chain_.m1 * (it->v_after - it->v_before);
  // A rest's part in (t0, t1]: the integral of N over [a, b], which the upper mass's momentum
  // gives (the lower one does not move), m2 (x2'(b) - x2'(a)) - (m1 + m2) g (b - a).
  const auto rest = std::upper_bound(rests_.begin(), rests_.end(), t0,
                                     [](double x, const ChainRest& r) { return x < r.lift; });
  for (auto it = rest; it < rests_.end() && it->t < t1; ++it) {
    const double a = std::fmax(it->t, t0), b = std::fmin(it->lift, t1);
    sum += chain_.m2 * (at(b).v(1) - at(a).v(1)) - (chain_.m1 + chain_.m2) * chain_.g * (b - a);
  }
  return sum;
}

ChainReferenceStepper::ChainReferenceStepper(const Chain& chain, double h,
                                             const ChainReferenceParams& params)
    : chain_(chain), h_(h), params_(params) {
  check_chain(chain);
  if (!(std::isfinite(h) && h > 0))
    throw std::invalid_argument("chain reference: h = " + std::to_string(h) +
                                " is out of range: finite, > 0");
}

void ChainReferenceStepper::initialize(const ChainState& s, std::int64_t l) {
  start_ = l;
  ChainReferenceParams params = params_;
  params.t_end = std::max(params_.t_end - static_cast<double>(l) * h_, 0.0);
  reference_.emplace(chain_, s, params);
}

StepInfo ChainReferenceStepper::do_step(ChainState& s, std::int64_t l) {
  const double t0 = static_cast<double>(l - start_) * h_,
               t1 = static_cast<double>(l + 1 - start_) * h_;
  s = reference_->at(t1);
  StepInfo info;
  info.contact_force = reference_->impulse(t0, t1) / h_;
  return info;
}

}  // namespace impact
