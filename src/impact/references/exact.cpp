// The exact solution of (2-1)-(2-4) with a constant body force; conventions in exact.hpp.
// Every quantity is a closed form in the data (phi, f, e, u0, v0) and the impact index k, so that
// nothing drifts after many bounces, and each formula is written in the form that does not cancel
// when the gap u - phi or the speed is tiny next to the other terms.
#include "impact/references/exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "impact/model/contact_law.hpp"

namespace impact {

namespace {

// impacts_until() from the Zeno time on, when infinitely many impacts have happened.
constexpr std::int64_t kZenoCount = std::numeric_limits<std::int64_t>::max() / 2;
// Largest flight count the logarithmic estimate in impacts_until() is allowed to produce; far
// below kZenoCount, and beyond anything reachable before t_inf (see impacts_until()).
constexpr double kMaxFlightEstimate = 1e18;

// sqrt(2 a b), a, b >= 0, without overflow of the product.
double sqrt_2ab(double a, double b) {
  const double p = 2.0 * a * b;
  if (std::isfinite(p)) return std::sqrt(p);
  return std::sqrt(2.0) * std::sqrt(a) * std::sqrt(b);
}

// Impact speed sqrt(v^2 + 2 g d) of a particle a height d >= 0 above the floor with velocity v,
// falling under g = -f > 0: energy (3-1) is conserved in flight. A sum of non-negative terms, so
// it does not cancel; fma keeps v^2 exact (it matters when 2 g d is tiny next to v^2).
double falling_speed(double v, double g, double d) {
  const double s = std::fma(v, v, 2.0 * g * d);
  if (std::isfinite(s)) return std::sqrt(s);
  return std::hypot(v, sqrt_2ab(g, d));
}

// Impact speed sqrt(v^2 - 2 f d) against an upward force f > 0, if the particle (v < 0) reaches
// the floor with a non-zero speed; nullopt when it turns back first or only grazes it.
std::optional<double> braked_speed(double v, double f, double d) {
  const double two_fd = 2.0 * f * d;
  if (std::isfinite(v * v) && std::isfinite(two_fd)) {
    // One rounding: v^2 - 2 f d keeps its sign, so the reach/no-reach decision is exact up to the
    // rounding of 2 f d.
    const double s = std::fma(v, v, -two_fd);
    if (s > 0.0) return std::sqrt(s);
    return std::nullopt;
  }
  const double a = std::fabs(v), b = sqrt_2ab(f, d);
  if (a > b) return std::sqrt(a - b) * std::sqrt(a + b);
  return std::nullopt;
}

}  // namespace

// The bounce algebra, with access to the private data.
struct ExactSolution::Impl {
  // More than one impact is possible only with a downward force and e > 0.
  static bool bounces(const ExactSolution& x) {
    return x.t1_ && x.model_.f < 0.0 && x.V1_ > 0.0 && x.e_ > 0.0;
  }
  // log(e) for 0 < e < 1; e - 1 is exact for e >= 1/2 (Sterbenz), so this keeps full relative
  // accuracy when e is close to 1, where log(e) would otherwise be a difference of nearby numbers.
  static double log_e(const ExactSolution& x) { return std::log1p(x.e_ - 1.0); }
  // e^n by pow (within an ulp for any n), not exp(n log e), whose error grows with n.
  static double pow_e(const ExactSolution& x, std::int64_t n) {
    return n == 0 ? 1.0 : std::pow(x.e_, static_cast<double>(n));
  }
  // Flight time 2 V1 / g of a bounce that leaves the floor with the first impact speed V1.
  static double period(const ExactSolution& x) { return 2.0 * x.V1_ / -x.model_.f; }
  // t_inf - t1 = (2 V1 / g) e / (1 - e) for e < 1: the flights after the first impact.
  static double zeno_span(const ExactSolution& x) { return period(x) * (x.e_ / (1.0 - x.e_)); }
  // sum_{j=n}^{n+m-1} e^j (bounces() only). For e < 1 it is e^n (1 - e^m) / (1 - e) with
  // 1 - e^m = -expm1(m log e): no cancellation when e^m is close to 1 (e near 1, m small).
  static double power_sum(const ExactSolution& x, std::int64_t n, std::int64_t m) {
    if (m <= 0) return 0.0;
    if (x.e_ == 1.0) return static_cast<double>(m);
    return pow_e(x, n) * (-std::expm1(static_cast<double>(m) * log_e(x)) / (1.0 - x.e_));
  }
  // sum_{j=n}^inf e^j = e^n / (1 - e) for e < 1: the impacts from the (n+1)-th on, up to t_inf.
  static double power_tail(const ExactSolution& x, std::int64_t n) {
    return pow_e(x, n) / (1.0 - x.e_);
  }
};

ExactSolution::ExactSolution(const Model& model, const State& initial)
    : model_(model), initial_(initial), e_(newton_e(contact_law(model, kElasticReading))) {
  if (!std::isfinite(model.phi) || !std::isfinite(model.f) || !std::isfinite(initial.u) ||
      !std::isfinite(initial.v))
    throw std::invalid_argument("ExactSolution: phi, f, u0 and v0 must be finite");
  if (!(e_ >= 0.0 && e_ <= 1.0))
    throw std::invalid_argument("ExactSolution: COR must be in [0, 1]");
  if (initial.u < model.phi) throw std::invalid_argument("ExactSolution: u0 must be >= phi, (2-2)");
  if (!model.expression.empty() || (model.harmonic && model.harmonic->amplitude != 0.0))
    throw std::invalid_argument(
        "ExactSolution: the closed form is for a constant force; a harmonic one is followed by "
        "ClosedFormMarch (method exact), an expression by method event_driven");

  const double d = initial.u - model.phi, v0 = initial.v, f = model.f;
  // The first impact s: the root of d + v0 s + f s^2 / 2 = 0 that is reached first, in the form
  // without cancellation: 2 d / (V1 - v0) when v0 < 0 (V1 - v0 = V1 + |v0| adds magnitudes),
  // (v0 + V1) / g when v0 >= 0 under g = -f > 0. With d = 0 and v0 < 0 this is s = 0 exactly,
  // the impact at 0+ of exact.hpp.
  std::optional<double> s;
  if (f < 0.0) {
    const double g = -f, V = falling_speed(v0, g, d);
    if (V == 0.0) {  // on the floor with v0 = 0: N = -f >= 0 holds it there from t = 0
      rest_ = 0.0;
      return;
    }
    s = v0 < 0.0 ? 2.0 * d / (V - v0) : (v0 + V) / g;
    V1_ = V;
  } else if (v0 < 0.0) {
    if (f == 0.0) {
      s = d / -v0;
      V1_ = -v0;
    } else if (const auto V = braked_speed(v0, f, d)) {
      s = 2.0 * d / (*V - v0);  // the smaller root: the particle stops before the larger one
      V1_ = *V;
    }
  } else if (f == 0.0 && v0 == 0.0 && d == 0.0) {
    rest_ = 0.0;  // on the floor, no force: stays there with N = 0
    return;
  }
  if (!s || !std::isfinite(*s)) {  // no impact, or one beyond any representable time
    V1_ = 0.0;
    return;
  }
  t1_ = s;
  if (e_ == 0.0) {
    // Plastic impact: v = 0 on the floor, where f <= 0 keeps it (f > 0 lifts it off again).
    if (f <= 0.0) rest_ = t1_;
  } else if (e_ < 1.0 && f < 0.0) {
    const double t_inf = *t1_ + Impl::zeno_span(*this);
    if (std::isfinite(t_inf)) rest_ = t_inf;
  }
}

std::optional<double> ExactSolution::impact_time(std::int64_t k) const {
  if (!t1_ || k < 1) return std::nullopt;
  if (k == 1) return t1_;
  if (!Impl::bounces(*this)) return std::nullopt;
  // t_k = t1 + (2 V1 / g) sum_{j=1}^{k-1} e^j, straight from k: each flight after impact j lasts
  // 2 e^j V1 / g. For e < 1 the sum is (t_inf - t1) (1 - e^(k-1)) with 1 - e^(k-1) <= 1, so
  // t_k <= rest_time() also after rounding.
  const double m = static_cast<double>(k - 1);
  const double t = e_ == 1.0 ? *t1_ + m * Impl::period(*this)
                             : *t1_ + Impl::zeno_span(*this) * -std::expm1(m * Impl::log_e(*this));
  if (!std::isfinite(t)) return std::nullopt;
  return t;
}

std::optional<double> ExactSolution::impact_speed(std::int64_t k) const {
  if (!impact_time(k)) return std::nullopt;
  return V1_ * Impl::pow_e(*this, k - 1);  // each impact returns e times the speed it receives
}

std::optional<double> ExactSolution::rest_time() const {
  return rest_;
}

std::int64_t ExactSolution::impacts_until(double t) const {
  // (0, t] is empty for t <= 0; an impact at t1 = 0 is counted for every t > 0 (impact at 0+).
  if (!t1_ || !(t > 0.0) || t < *t1_) return 0;
  if (!Impl::bounces(*this)) return 1;
  if (rest_ && t >= *rest_) return kZenoCount;
  // Invert t_k <= t for the number m = k - 1 of completed flights, with r = (t - t1) / (2 V1 / g):
  // m = floor(r) for e = 1; for e < 1, sum_{j=1}^m e^j <= r gives e^m >= 1 - r (1 - e) / e, i.e.
  // m = floor(log1p(-x) / log e) with x = r (1 - e) / e < 1 before t_inf. Since 1 - x >= 2^-53
  // when x rounds below 1, m <= 37 / |log e|, far below the caps.
  const double r = (t - *t1_) / Impl::period(*this);
  double m = kMaxFlightEstimate;
  if (e_ == 1.0) {
    m = std::floor(r);
  } else {
    const double x = r * ((1.0 - e_) / e_);
    if (x < 1.0) m = std::floor(std::log1p(-x) / Impl::log_e(*this));
  }
  std::int64_t k = 1 + static_cast<std::int64_t>(std::clamp(m, 0.0, kMaxFlightEstimate));
  // The rounding in r and in the logarithm can put the estimate one off; the closed-form impact
  // times decide, so that impacts_until() and impact_time() agree: t_k <= t < t_{k+1}.
  const auto time_of = [this](std::int64_t j) {
    return impact_time(j).value_or(std::numeric_limits<double>::infinity());
  };
  for (int i = 0; i < 4 && k > 1 && time_of(k) > t; ++i) --k;
  for (int i = 0; i < 4 && time_of(k + 1) <= t; ++i) ++k;
  if (time_of(k) <= t && t < time_of(k + 1)) return k;
  // Right before t_inf, 1 - x is a few ulp and the estimate can be off by more (and x can round
  // to 1). Bisect on the closed-form times instead: at most 62 steps, and the invariant
  // t_lo <= t < t_hi brackets t whether or not rounding keeps the t_k monotone.
  std::int64_t lo = 1, hi = kZenoCount;
  if (time_of(hi) <= t) return kZenoCount;  // e = 1 with a vanishing flight time
  while (hi - lo > 1) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    (time_of(mid) <= t ? lo : hi) = mid;
  }
  return lo;
}

State ExactSolution::at(double t) const {
  if (!(t > 0.0)) return initial_;
  if (rest_ && t >= *rest_) return {model_.phi, 0.0};
  return flight_state(flight_at(t), t);
}

ExactSolution::Flight ExactSolution::flight_at(double t) const {
  Flight flight;
  flight.k = impacts_until(t);
  const double never = std::numeric_limits<double>::infinity();
  flight.begin = flight.k == 0 ? 0.0 : impact_time(flight.k).value_or(t);
  flight.end = impact_time(flight.k + 1).value_or(never);
  if (rest_) flight.end = std::min(flight.end, *rest_);
  // Flight after impact k leaves the floor with e^k V1 (Newton's law applied k times).
  if (flight.k > 0) flight.launch = V1_ * Impl::pow_e(*this, flight.k);
  return flight;
}

State ExactSolution::flight_state(const Flight& flight, double t) const {
  const double phi = model_.phi, f = model_.f;
  // The gap u - phi is computed as a gap and added to phi last, so a far floor (phi = 1e6) costs
  // only the final rounding of u, not the accuracy of the gap itself.
  double gap = 0.0, v = 0.0;
  if (flight.k == 0) {
    gap = (initial_.u - phi) + t * (initial_.v + 0.5 * f * t);
    v = initial_.v + f * t;
  } else {
    // u and v both come from the same tau, so the state lies on the energy level w^2/2 - f phi
    // (3-1) even where tau carries the rounding of t_k.
    const double w = flight.launch;
    double tau = std::max(0.0, t - flight.begin);
    if (f < 0.0) tau = std::min(tau, 2.0 * w / -f);  // the flight ends at impact k + 1
    gap = tau * (w + 0.5 * f * tau);
    v = w + f * tau;
  }
  // In flight the exact gap is >= 0; only rounding next to an impact can make it negative.
  return {phi + std::max(gap, 0.0), v};
}

double ExactSolution::impulse(double t0, double t1) const {
  if (!(t1 > t0)) return 0.0;
  double J = 0.0;
  const std::int64_t n0 = impacts_until(t0), n1 = impacts_until(t1);
  if (n1 > n0) {
    // Impact k changes v from -V_k to e V_k: an impulse (1 + e) V_k = (1 + e) e^(k-1) V1, summed
    // over k = n0 + 1 .. n1 as a geometric series in closed form; up to t_inf the whole tail.
    if (!Impl::bounces(*this)) {
      J += (1.0 + e_) * V1_;  // the only impact
    } else if (rest_ && t1 >= *rest_) {
      J += (1.0 + e_) * V1_ * Impl::power_tail(*this, n0);
    } else {
      J += (1.0 + e_) * V1_ * Impl::power_sum(*this, n0, n1 - n0);
    }
  }
  // Resting on the floor: u'' = 0, so N = -f (2-1) for the time spent at rest within (t0, t1].
  if (rest_ && model_.f < 0.0) J += -model_.f * std::max(0.0, t1 - std::max(t0, *rest_));
  return J;
}

ExactStepper::ExactStepper(const Model& model, double h, const ExactParams& params)
    : model_(model), h_(h), max_events_(params.max_events) {
  if (params.max_events < 0)
    throw std::invalid_argument("method 'exact': max_events must be >= 0 (0: automatic)");
  if (!model.expression.empty())
    throw std::invalid_argument(
        "method 'exact' has no closed-form flight for a force expression; use method "
        "'event_driven'");
  if (model.harmonic && model.harmonic->amplitude != 0.0) {
    sin_h_ = std::sin(model.harmonic->omega * h);
    cos_h_ = std::cos(model.harmonic->omega * h);
  }
}

void ExactStepper::initialize(const State& s, std::int64_t l) {
  l0_ = l;
  rotation_l_ = -1;
  flight_ = {};
  if (model_.linear) {
    linear_.emplace(linear_track(model_, s, static_cast<double>(l) * h_));
    linear_->set_event_sink(sink_);
  } else if (model_.harmonic && model_.harmonic->amplitude != 0.0) {
    track_.emplace(model_, s, static_cast<double>(l) * h_);
    track_->set_event_sink(sink_);
  } else {
    Model constant = model_;
    constant.harmonic.reset();
    solution_.emplace(constant, s);
    rest_begin_ = solution_->rest_time().value_or(std::numeric_limits<double>::infinity());
    rest_force_ = constant.f < 0.0 ? -constant.f : 0.0;
  }
}

void ExactStepper::set_event_sink(EventSink sink) {
  sink_ = std::move(sink);
  if (track_) track_->set_event_sink(sink_);
  if (linear_) linear_->set_event_sink(sink_);
}

StepInfo ExactStepper::closed_form_step(State& s, double t0, double t1) {
  s = solution_->at(t1);
  StepInfo info;
  info.contact_force = solution_->impulse(t0, t1) / h_;
  if (sink_) emit_closed_form_events(t0, t1);
  const auto rest = solution_->rest_time();
  flight_ = t1 > 0.0 && !(rest && t1 >= *rest) ? solution_->flight_at(t1) : ExactSolution::Flight{};
  return info;
}

// The impacts in (t0, t1] and the start of the rest, at grid time l0 h + t.
void ExactStepper::emit_closed_form_events(double t0, double t1) const {
  const double origin = static_cast<double>(l0_) * h_, e = solution_->e();
  const auto rest = solution_->rest_time();
  const std::int64_t first = solution_->impacts_until(t0) + 1, last = solution_->impacts_until(t1);
  const double V1 = solution_->impact_speed(1).value_or(0.0);
  for (std::int64_t k = first; k <= last; ++k) {
    const auto t = solution_->impact_time(k);
    const auto V = solution_->impact_speed(k);
    if (!t || !V || (rest && *V < kChatterCutoff * V1 && k > 1)) break;
    sink_(Event{origin + *t, EventKind::impact, -*V, (rest && *t == *rest) ? 0.0 : e * *V});
  }
  if (rest && *rest <= t1 && (t0 < *rest || (*rest == 0.0 && t0 == 0.0)))
    sink_(Event{origin + *rest, EventKind::stick, 0.0, 0.0});
}

StepInfo ExactStepper::harmonic_step(State& s, std::int64_t l) {
  const double t1 = static_cast<double>(l + 1) * h_;
  if (const HarmonicFlight* flight = track_->free_flight_until(t1)) {
    if (l == rotation_l_ && ++since_anchor_ < kRotationAnchor) {
      const double sin1 = sin_ * cos_h_ + cos_ * sin_h_;
      cos_ = cos_ * cos_h_ - sin_ * sin_h_;
      sin_ = sin1;
    } else {
      const double theta = flight->theta(t1);
      sin_ = std::sin(theta);
      cos_ = std::cos(theta);
      since_anchor_ = 0;
    }
    rotation_l_ = l + 1;
    // Near the flight's anchor the rotation's differences would carry (a/omega^2) ulp(sin)
    // against terms of size a dt^2 (harmonic_series.hpp): there the flight in x = omega dt.
    const State g =
        flight->near_anchor(t1) ? flight->at_near_anchor(t1) : flight->at(t1, sin_, cos_);
    s = {track_->phi() + std::max(g.u, 0.0), g.v};
    return {};
  }
  StepInfo info;
  double impulse = 0.0;
  event_limit_ = run_budget(max_events_, l + 1 - l0_);
  track_->set_event_limit(event_limit_);
  s = track_->advance(t1, impulse);
  info.contact_force = impulse / h_;
  info.converged = track_->converged();
  return info;
}

// A linear force's flights are sampled through the track at every step (a closed form per sample).
StepInfo ExactStepper::linear_step(State& s, std::int64_t l) {
  StepInfo info;
  double impulse = 0.0;
  event_limit_ = run_budget(max_events_, l + 1 - l0_);
  linear_->set_event_limit(event_limit_);
  s = linear_->advance(static_cast<double>(l + 1) * h_, impulse);
  info.contact_force = impulse / h_;
  info.converged = linear_->converged();
  return info;
}

std::string ExactStepper::failure_reason() const {
  if (linear_) return describe_stop(linear_->stop(), {}, max_events_, event_limit_);
  if (!track_) return {};
  return describe_stop(track_->stop(), {}, max_events_, event_limit_);
}

}  // namespace impact
