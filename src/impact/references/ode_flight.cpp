// The ODE flights of ode_flight.hpp: GSL odeiv2 rk8pd between impacts.
#include "impact/references/ode_flight.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <utility>

#include "impact/forces/gsl_errors.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/rk8pd.hpp"

namespace impact {

namespace {

constexpr int kSamples = 9;  // force samples per ODE step, ends included (ode_flight.hpp)

}  // namespace

int FlightRhs::operator()(double t, const double y[], double dydt[]) const {
  dydt[0] = y[1];
  const State s{phi + y[0], y[1]};
  if (rates) force.set_internal(rates->evaluate(t, s, y + 2, dydt + 2));
  dydt[1] = force.at(t, s);
  if (bonds) {
    const double beta = bond_fraction(*bonds, y[bond_at + kBondFraction]);
    const BondRates rates = bond_rates(*bonds, beta, y[0]);
    dydt[1] -= adhesive_pull(*bonds, beta, y[0]);
    dydt[bond_at + kBondFraction] = rates.carried;
    dydt[bond_at + kBondEnergy] = rates.spent;
  }
  return GSL_SUCCESS;
}

OdeLaw::OdeLaw(const Model& model, const OdeSettings& settings)
    : phi_(model.phi),
      rest_{model.phi, 0.0},
      settings_(settings),
      flight_(2 + model.internal.size() + (bonded(model) ? 2 : 0), settings.atol, settings.rtol,
              FlightRhs{ForceFunction(model),
                        model.internal.empty() ? std::nullopt
                                               : std::optional<InternalRates>(std::in_place, model),
                        bonded(model) ? model.bonding : std::nullopt, 2 + model.internal.size(),
                        model.phi}),
      internal_count_(model.internal.size() + (bonded(model) ? 2 : 0)),
      rate_count_(model.internal.size()),
      bonds_(flight_.rhs().bonds) {
  set_internal(with_internal(model, {}).z);
  if (rate_count_ > 0) floor_.emplace(model, settings.rtol, settings.atol, settings.max_step);
}

void OdeLaw::set_internal(const std::array<double, kMaxInternal>& z) {
  z_a_ = z_b_ = z;
  if (bonds_)
    z_a_[rate_count_ + kBondFraction] = bond_carried(*bonds_, z[rate_count_ + kBondFraction]);
  z_b_ = z_a_;
}

void OdeLaw::keep_bonds_monotone(std::array<double, kMaxInternal>& z) const {
  if (!bonds_) return;
  double& carried = z[rate_count_ + kBondFraction];
  double& spent = z[rate_count_ + kBondEnergy];
  carried = bond_carried_monotone(*bonds_, carried, z_a_[rate_count_ + kBondFraction]);
  spent = std::fmax(spent, z_a_[rate_count_ + kBondEnergy]);
}

void OdeLaw::start(double t, double gap, double v, bool at_crossing) {
  if (internal_count_ > 0) {
    // Where the flight starts: on the floor, or inside the ODE step it left (an impact's launch);
    // the first start keeps the initial values.
    if (on_floor_ || t_b_ > t_a_) z_b_ = floor_internal(t);
    z_a_ = z_b_;
    on_floor_ = false;
  }
  gsl_odeiv2_evolve_reset(flight_.rk().evolve);
  flight_.rk().h_next = settings_.max_step / 4;
  t_a_ = t_b_ = certified_ = checked_ = t;
  y_a_ = y_b_ = {gap, v};
  departing_ = gap == 0.0 && v == 0.0;
  at_crossing_ = at_crossing;
}

State OdeLaw::at(double t) const {
  State y;
  std::array<double, kMaxInternal> z;
  dense(t, y, z);
  return y;
}

void OdeLaw::dense(double t, State& state, std::array<double, kMaxInternal>& z) const {
  state = y_a_;
  z = z_a_;
  if (!(t > t_a_)) return;
  state = y_b_;
  z = z_b_;
  if (t == t_b_) return;
  GslErrorsAsStatus quiet;
  const std::size_t n = 2 + internal_count_;
  std::array<double, 2 + kMaxInternal> y{y_a_.u, y_a_.v}, error{}, rate_in{};
  std::copy(z_a_.begin(), z_a_.end(), y.begin() + 2);
  if (internal_count_ > 0) {
    // The rates at the step's start, as the rhs gives them.
    flight_.evaluate(t_a_, y.data(), rate_in.data());
    flight_.rk().rethrow();
  } else {
    rate_in = {y_a_.v, force_on(t_a_, y_a_, z_a_)};
  }
  gsl_odeiv2_step_reset(flight_.rk().dense);
  const int status =
      gsl_odeiv2_step_apply(flight_.rk().dense, t_a_, t - t_a_, y.data(), error.data(),
                            rate_in.data(), nullptr, &flight_.rk().sys);
  flight_.rk().rethrow();
  if (status != GSL_SUCCESS) return;
  state = {y[0], y[1]};
  std::copy(y.begin() + 2, y.begin() + 2 + static_cast<std::ptrdiff_t>(n - 2), z.begin());
  keep_bonds_monotone(z);
}

std::array<double, kMaxInternal> OdeLaw::floor_internal(double t) const {
  if (on_floor_ && t >= floor_from_) return floor_ ? floor_->at(t) : z_floor_;
  State y;
  std::array<double, kMaxInternal> z;
  dense(t, y, z);
  return z;
}

std::array<double, kMaxInternal> OdeLaw::internal_at(double t) const {
  if (internal_count_ == 0) return z_b_;
  std::array<double, kMaxInternal> z = floor_internal(t);
  if (bonds_)
    z[rate_count_ + kBondFraction] = bond_fraction(*bonds_, z[rate_count_ + kBondFraction]);
  return z;
}

void OdeLaw::reach_floor(double t) {
  if (internal_count_ == 0) return;
  State y;
  std::array<double, kMaxInternal> z;
  dense(t, y, z);
  if (floor_) floor_->start(t, z);
  floor_from_ = t;
  z_floor_ = z;
  on_floor_ = true;
}

void OdeLaw::take_step() {
  GslErrorsAsStatus quiet;
  t_a_ = t_b_;
  y_a_ = y_b_;
  z_a_ = z_b_;
  double t = t_a_;
  std::array<double, 2 + kMaxInternal> y{y_a_.u, y_a_.v};
  std::copy(z_a_.begin(), z_a_.end(), y.begin() + 2);
  const double stop = std::fmin(t_a_ + settings_.max_step, settings_.end);
  const int status =
      gsl_odeiv2_evolve_apply(flight_.rk().evolve, flight_.rk().control, flight_.rk().step,
                              &flight_.rk().sys, &t, stop, &flight_.rk().h_next, y.data());
  flight_.rk().rethrow();
  const bool finite =
      std::all_of(y.begin(), y.begin() + 2 + static_cast<std::ptrdiff_t>(internal_count_),
                  [](double x) { return std::isfinite(x); });
  if (status != GSL_SUCCESS || !(t > t_a_) || !finite) {
    ode_ok_ = false;
    failed_status_ = status;
    return;
  }
  ++ode_steps_;
  t_b_ = t;
  y_b_ = {y[0], y[1]};
  std::copy(y.begin() + 2, y.end(), z_b_.begin());
  keep_bonds_monotone(z_b_);
  // The step's force bound (ode_flight.hpp).
  std::array<double, kSamples> f{};
  double largest = 0, change = 0;
  const bool state = flight_.rhs().force.state_dependent() || bonds_;
  for (int i = 0; i < kSamples; ++i) {
    const double t_i = t_a_ + (t_b_ - t_a_) * i / (kSamples - 1);
    if (!state) {
      f[i] = force(t_i);
    } else {  // along the path (ode_flight.hpp)
      State y_i;
      std::array<double, kMaxInternal> z_i;
      dense(t_i, y_i, z_i);
      f[i] = force_on(t_i, y_i, z_i);
    }
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
  if (y_b_.u <= 0.0 && y_b_.v <= 0.0) {
    reach_floor(t_b_);
    return detail::contact_at(t_b_, y_b_, force(t_b_), t_b_ - checked_);
  }
  certified_ = std::numeric_limits<double>::infinity();
  return std::nullopt;
}

std::optional<Contact> OdeLaw::search(double horizon, long& budget) {
  const long budget_given = budget, ode_steps_before = ode_steps_;
  const double from = t_b_;
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
    if (auto contact = search_contact(*this, bound_, certified_, checked_, horizon, budget, t_b_)) {
      reach_floor(contact->t);
      return contact;
    }
  }
  if (!ode_ok_ || out_of_steps_) budget = 0;
  // A search that spent its budget on ODE steps did not stall on a contact: rk8pd's error control
  // kept its steps that short (a stiff rate or force).
  if (budget <= 0 && ode_ok_ && !out_of_steps_ &&
      2 * (ode_steps_ - ode_steps_before) >= budget_given) {
    stiff_ = true;
    stiff_from_ = from;
  }
  return std::nullopt;
}

std::string OdeLaw::failure() const {
  std::ostringstream msg;
  msg.precision(6);
  // What sets rk8pd's step: the force, and the internal variables' rates where there are some.
  const std::string varies =
      internal_count_ > 0 ? "the force or an internal variable's rate varies" : "the force varies";
  if (out_of_steps_)
    msg << "rk8pd used up the run's budget of ODE steps (" << ode_steps_ << " by t = " << t_b_
        << "; method.max_ode_steps, 0: automatic, " << kAutomaticBudget << " + "
        << kAutomaticBudgetPerGridStep << " per grid step): " << varies << " on a scale of about "
        << (t_b_ - t_a_) << " s (its last step); raise method.max_ode_steps, or shorten time.T";
  else if (stiff_)
    msg << "rk8pd's error control (rtol = " << settings_.rtol << ", atol = " << settings_.atol
        << ") took steps of about " << (t_b_ - t_a_) << " s from t = " << stiff_from_
        << " and reached only t = " << t_b_ << " in a million of them: " << varies
        << " on that scale, a stiff system for rk8pd, an explicit method (not a contact: the "
           "particle is in flight there); a rate or force with a slower time scale, or a time "
           "stepper (direct, moreau_jean), can run it";
  else if (!ode_ok_)
    msg << "rk8pd could not take a step from t = " << t_b_ << " within rtol = " << settings_.rtol
        << ", atol = " << settings_.atol << " (GSL: " << gsl_strerror(failed_status_)
        << "): the force is unbounded or not smooth enough near there";
  return msg.str();
}

}  // namespace impact
