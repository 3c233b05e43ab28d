// The ODE flights of ode_flight.hpp: GSL odeiv2 rk8pd between impacts.
#include "impact/ode_flight.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <utility>

#include "impact/event_track.hpp"
#include "impact/gsl_errors.hpp"

namespace impact {

namespace {

constexpr int kSamples = 9;         // force samples per ODE step, ends included (ode_flight.hpp)
constexpr int kLiftScan = 4096;     // samples of f per lift-off scan before the track asks again
constexpr int kLiftSpacing = 8;     // lift-off scan spacing: max_step / kLiftSpacing
constexpr int kChatterSamples = 5;  // samples of f over a chatter window
// The lift-off scan's search between two samples (hidden_rise): the split point's fraction and
// the depth, which reaches 1e-9 of the spacing.
constexpr double kLiftSplit = 0.41421356237309503;  // sqrt(2) - 1
constexpr int kLiftDepth = 30;
constexpr int kLiftRescan = 8;  // samples before a lift-off's root, looking for an earlier one

}  // namespace

// The GSL objects; on the heap, since the system's params point here.
struct OdeLaw::Gsl {
  Gsl(const ForceFunction* f, double floor, const OdeSettings& s) : force(f), phi(floor) {
    sys = gsl_odeiv2_system{&Gsl::rhs, nullptr, 2, this};
    step = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    dense = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    control = gsl_odeiv2_control_y_new(s.atol, s.rtol);
    evolve = gsl_odeiv2_evolve_alloc(2);
  }
  Gsl(const Gsl&) = delete;
  Gsl& operator=(const Gsl&) = delete;
  ~Gsl() {
    gsl_odeiv2_evolve_free(evolve);
    gsl_odeiv2_control_free(control);
    gsl_odeiv2_step_free(dense);
    gsl_odeiv2_step_free(step);
  }
  // y = (u - phi, v): y' = (v, f(t, u, v)). A force that fails (an expression that is not finite)
  // is kept and rethrown after GSL returns, rather than thrown through GSL's C frames.
  static int rhs(double t, const double y[], double dydt[], void* self) {
    auto* g = static_cast<Gsl*>(self);
    dydt[0] = y[1];
    try {
      dydt[1] = g->force->at(t, {g->phi + y[0], y[1]});
    } catch (...) {
      g->error = std::current_exception();
      return GSL_EBADFUNC;
    }
    return GSL_SUCCESS;
  }
  void rethrow() {
    if (error) std::rethrow_exception(std::exchange(error, nullptr));
  }

  const ForceFunction* force;
  double phi;
  gsl_odeiv2_system sys{};
  gsl_odeiv2_step* step;
  gsl_odeiv2_step* dense;
  gsl_odeiv2_control* control;
  gsl_odeiv2_evolve* evolve;
  std::exception_ptr error;
  double h_next = 0;
};

OdeLaw::OdeLaw(const Model& model, const OdeSettings& settings)
    : force_(std::make_unique<ForceFunction>(model)),
      phi_(model.phi),
      rest_{model.phi, 0.0},
      settings_(settings),
      gsl_(std::make_unique<Gsl>(force_.get(), phi_, settings)) {}

OdeLaw::OdeLaw(const OdeLaw& other)
    : force_(std::make_unique<ForceFunction>(*other.force_)),
      phi_(other.phi_),
      rest_(other.rest_),
      settings_(other.settings_),
      gsl_(std::make_unique<Gsl>(force_.get(), phi_, settings_)),
      t_a_(other.t_a_),
      t_b_(other.t_b_),
      y_a_(other.y_a_),
      y_b_(other.y_b_),
      bound_(other.bound_),
      certified_(other.certified_),
      checked_(other.checked_),
      departing_(other.departing_),
      at_crossing_(other.at_crossing_),
      ode_steps_(other.ode_steps_),
      ode_step_limit_(other.ode_step_limit_),
      ode_ok_(other.ode_ok_),
      out_of_steps_(other.out_of_steps_),
      failed_status_(other.failed_status_) {
  gsl_->h_next = other.gsl_->h_next;
}

OdeLaw& OdeLaw::operator=(const OdeLaw& other) {
  if (this != &other) *this = OdeLaw(other);
  return *this;
}

OdeLaw::OdeLaw(OdeLaw&&) noexcept = default;
OdeLaw& OdeLaw::operator=(OdeLaw&&) noexcept = default;
OdeLaw::~OdeLaw() = default;

void OdeLaw::start(double t, double gap, double v, bool at_crossing) {
  gsl_odeiv2_evolve_reset(gsl_->evolve);
  gsl_->h_next = settings_.max_step / 4;
  t_a_ = t_b_ = certified_ = checked_ = t;
  y_a_ = y_b_ = {gap, v};
  departing_ = gap == 0.0 && v == 0.0;
  at_crossing_ = at_crossing;
}

State OdeLaw::at(double t) const {
  if (!(t > t_a_)) return y_a_;
  if (t == t_b_) return y_b_;
  GslErrorsAsStatus quiet;
  double y[2] = {y_a_.u, y_a_.v}, error[2], rate_in[2] = {y_a_.v, force_on(t_a_, y_a_)};
  gsl_odeiv2_step_reset(gsl_->dense);
  const int status =
      gsl_odeiv2_step_apply(gsl_->dense, t_a_, t - t_a_, y, error, rate_in, nullptr, &gsl_->sys);
  gsl_->rethrow();
  if (status != GSL_SUCCESS) return y_b_;
  return {y[0], y[1]};
}

void OdeLaw::take_step() {
  GslErrorsAsStatus quiet;
  t_a_ = t_b_;
  y_a_ = y_b_;
  double t = t_a_, y[2] = {y_a_.u, y_a_.v};
  const double stop = std::fmin(t_a_ + settings_.max_step, settings_.end);
  const int status = gsl_odeiv2_evolve_apply(gsl_->evolve, gsl_->control, gsl_->step, &gsl_->sys,
                                             &t, stop, &gsl_->h_next, y);
  gsl_->rethrow();
  if (status != GSL_SUCCESS || !(t > t_a_) || !std::isfinite(y[0]) || !std::isfinite(y[1])) {
    ode_ok_ = false;
    failed_status_ = status;
    return;
  }
  ++ode_steps_;
  t_b_ = t;
  y_b_ = {y[0], y[1]};
  // The step's force bound (ode_flight.hpp).
  std::array<double, kSamples> f{};
  double largest = 0, change = 0;
  const bool state = force_->state_dependent();
  for (int i = 0; i < kSamples; ++i) {
    const double t_i = t_a_ + (t_b_ - t_a_) * i / (kSamples - 1);
    if (!state)
      f[i] = force(t_i);
    else  // along the path (ode_flight.hpp)
      f[i] = force_on(t_i, i == 0 ? y_a_ : i == kSamples - 1 ? y_b_ : at(t_i));
    largest = std::fmax(largest, std::fabs(f[i]));
    if (i > 0) change = std::fmax(change, std::fabs(f[i] - f[i - 1]));
  }
  bound_ = largest + change;
  // Leaving the floor with zero speed: g = g' = 0, and g'' = f > 0 up to the first sample where f
  // is not positive keeps g > 0 there.
  if (departing_) {
    departing_ = false;
    if (f[0] > 0.0 || at_crossing_) {
      int i = 1;
      for (; i < kSamples && f[i] > 0.0; ++i)
        certified_ = t_a_ + (t_b_ - t_a_) * i / (kSamples - 1);
      if (i == 1 && f[0] > 0.0) {
        // f turns down before the first sample: g'' = f > 0 up to its zero, past which (hi) the
        // search goes on, so that a particle that cannot leave rests from there.
        const auto force_at = [](double x, void* self) {
          return static_cast<const OdeLaw*>(self)->force(x);
        };
        certified_ =
            detail::refine_root(force_at, this, t_a_, t_a_ + (t_b_ - t_a_) / (kSamples - 1)).hi;
      }
    }
  }
}

// The contact search has reached the end of the run: a contact there, or none in the run.
std::optional<Contact> OdeLaw::at_end() {
  if (y_b_.u <= 0.0 && y_b_.v <= 0.0)
    return detail::contact_at(t_b_, y_b_, force(t_b_), t_b_ - checked_);
  certified_ = std::numeric_limits<double>::infinity();
  return std::nullopt;
}

std::optional<Contact> OdeLaw::search(double horizon, long& budget) {
  while (budget > 0 && ode_ok_ && certified_ <= horizon) {
    if (certified_ >= t_b_) {
      if (t_b_ >= settings_.end) return at_end();
      if (ode_steps_ >= ode_step_limit_) {
        out_of_steps_ = true;
        break;
      }
      --budget;
      take_step();
      continue;
    }
    if (auto contact = search_contact(*this, bound_, certified_, checked_, horizon, budget, t_b_))
      return contact;
  }
  if (!ode_ok_ || out_of_steps_) budget = 0;
  return std::nullopt;
}

std::string OdeLaw::failure() const {
  std::ostringstream msg;
  msg.precision(6);
  if (out_of_steps_)
    msg << "rk8pd used up the run's budget of ODE steps (" << ode_steps_ << " by t = " << t_b_
        << "; method.max_ode_steps, 0: automatic, " << kAutomaticBudget << " + "
        << kAutomaticBudgetPerGridStep << " per grid step): the force varies on a scale of about "
        << (t_b_ - t_a_) << " s (its last step); raise method.max_ode_steps, or shorten time.T";
  else if (!ode_ok_)
    msg << "rk8pd could not take a step from t = " << t_b_ << " within rtol = " << settings_.rtol
        << ", atol = " << settings_.atol << " (GSL: " << gsl_strerror(failed_status_)
        << "): the force is unbounded or not smooth enough near there";
  return msg.str();
}

// A central difference, one-sided at the start of time and at the end of the run.
double OdeLaw::rate(double t) const {
  const double d = 1e-6 * std::fmax(1.0, std::fabs(t));
  const double lo = t - d >= 0.0 ? t - d : t, hi = t + d <= settings_.end ? t + d : t;
  return (force(hi) - force(lo)) / (hi - lo);
}

// A positive excursion of f inside (a, b], where f(a) <= 0 and f(b) <= 0: f at a point p a
// non-dyadic fraction in (so that a force periodic in the scan's spacing is not sampled at one
// phase), positive there or not excluded by the samples' bound max f + the largest change between
// neighbours (as for an ODE step's force bound), halves searched in order to a depth of kLiftDepth.
// Returns a bracket [lo, hi] with f(lo) <= 0 < f(hi) of the first one found.
std::optional<detail::Bracket> OdeLaw::hidden_rise(double a, double fa, double b, double fb,
                                                   int depth) const {
  const double p = a + (b - a) * kLiftSplit, fp = force(p);
  if (fp > 0.0) return detail::Bracket{a, p};
  const double bound =
      std::fmax(fa, std::fmax(fp, fb)) + std::fmax(std::fabs(fp - fa), std::fabs(fb - fp));
  if (!(bound > 0.0) || depth == 0 || !(a < p && p < b)) return std::nullopt;
  if (const auto left = hidden_rise(a, fa, p, fp, depth - 1)) return left;
  return hidden_rise(p, fp, b, fb, depth - 1);
}

// The first upward crossing of f in (a, b], where f(a) <= 0 < f(b): Brent's root of f in [a, b],
// unless a positive excursion shows before it (kLiftRescan samples of what lies before the root,
// each gap searched by hidden_rise), whose own first crossing is then the one. A force faster than
// the scan crosses several times between two of its samples (the table at 1 kHz against a
// spacing of 1.25 ms: up, down, up), and Brent may converge to any of those crossings.
double OdeLaw::first_upward(double a, double fa, double b, int depth) const {
  if (fa == 0.0) return a;
  const auto minus_f = [](double x, void* self) {
    return -static_cast<const OdeLaw*>(self)->force(x);
  };
  const detail::Bracket root = detail::refine_root(minus_f, const_cast<OdeLaw*>(this), a, b);
  if (depth == 0) return root.hi;
  double x = a, fx = fa;
  for (int k = 1; k <= kLiftRescan; ++k) {
    const double y = a + (root.lo - a) * k / kLiftRescan, fy = force(y);
    if (fy > 0.0) return first_upward(x, fx, y, depth - 1);
    if (const auto rise = hidden_rise(x, fx, y, fy, kLiftDepth))
      return first_upward(rise->lo, force(rise->lo), rise->hi, depth - 1);
    x = y;
    fx = fy;
  }
  return root.hi;
}

Lift OdeLaw::lift_after(double t) const {
  double a = t, fa = force(a);
  if (fa > 0.0) return {t, true};
  const double spacing = settings_.max_step / kLiftSpacing;
  for (int k = 1; k <= kLiftScan; ++k) {
    const double b = std::fmin(t + spacing * k, settings_.end), fb = force(b);
    if (fb > 0.0) return {first_upward(a, fa, b, kLiftDepth), true};
    if (const auto rise = hidden_rise(a, fa, b, fb, kLiftDepth))
      return {first_upward(rise->lo, force(rise->lo), rise->hi, kLiftDepth), true};
    if (b >= settings_.end) return {std::numeric_limits<double>::infinity(), true};  // none
    a = b;
    fa = fb;
  }
  return {a, false};
}

double OdeLaw::rest_impulse(double a, double b) const {
  double value = 0;
  // Gauss-Legendre 16 per piece of at most max_step, as accurate as the ODE steps.
  for (double x = a; x < b; x += settings_.max_step)
    value -= force_->integral(x, std::fmin(b, x + settings_.max_step), rest_);
  return value;
}

std::optional<double> OdeLaw::chatter_window(double t, double V, double e) const {
  const double g = -force(t);
  if (!(g > 0.0)) return std::nullopt;
  const double W0 = chatter_trial_window(e, V, g);
  if (t + W0 > settings_.end) return std::nullopt;  // f is not known beyond the run
  // The samples' range widened by the largest change between neighbours (the bound of an ODE
  // step), so that a force varying faster than the samples does not pass for a steady one.
  double g_min = g, g_max = g, previous = g, change = 0;
  for (int i = 1; i < kChatterSamples; ++i) {
    const double ti = t + W0 * i / (kChatterSamples - 1), gi = -force(ti);
    g_min = std::fmin(g_min, gi);
    g_max = std::fmax(g_max, gi);
    change = std::fmax(change, std::fabs(gi - previous));
    previous = gi;
  }
  // A force of the state: the corners of the bounces' box at each time (ode_flight.hpp).
  if (force_->state_dependent()) {
    const double height = V * V / g;
    for (int i = 0; i < kChatterSamples; ++i) {
      const double ti = t + W0 * i / (kChatterSamples - 1);
      for (const State corner : {State{0, -V}, State{0, V}, State{height, -V}, State{height, V}}) {
        const double gi = -force_on(ti, corner);
        g_min = std::fmin(g_min, gi);
        g_max = std::fmax(g_max, gi);
      }
    }
  }
  return chatter_window_within(e, V, W0, g_min - change, g_max + change);
}

}  // namespace impact
