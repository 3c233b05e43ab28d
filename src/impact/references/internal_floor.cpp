#include "impact/references/internal_floor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "impact/forces/gsl_errors.hpp"
#include "impact/references/rk8pd.hpp"

namespace impact {

int FloorRhs::operator()(double t, const double y[], double dydt[]) const {
  rates.evaluate(t, {phi, 0.0}, y, dydt);
  return GSL_SUCCESS;
}

FloorInternal::FloorInternal(const Model& model, double rtol, double atol, double max_step)
    : system_(model.internal.size(), atol, rtol, FloorRhs{InternalRates(model), model.phi}),
      max_step_(max_step) {}

void FloorInternal::start(double t, const std::array<double, kMaxInternal>& z) {
  origin_ = t;
  nodes_.assign(1, Node{t, z});
  gsl_odeiv2_evolve_reset(system_.rk().evolve);
  system_.rk().h_next = max_step_ / 4;
}

// Accepted steps up to past t.
void FloorInternal::extend(double t) const {
  GslErrorsAsStatus quiet;
  const std::size_t n = system_.rhs().rates.size();
  while (nodes_.back().t < t) {
    Node next = nodes_.back();
    const double from = next.t;
    const int status = gsl_odeiv2_evolve_apply(
        system_.rk().evolve, system_.rk().control, system_.rk().step, &system_.rk().sys, &next.t,
        from + max_step_, &system_.rk().h_next, next.z.data());
    system_.rk().rethrow();
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) finite = finite && std::isfinite(next.z[i]);
    if (status != GSL_SUCCESS || !(next.t > from) || !finite)
      throw std::runtime_error(
          "the internal variables on the floor: rk8pd could not take a step "
          "from t = " +
          std::to_string(from) + " (GSL: " + gsl_strerror(status) +
          "): a rate is unbounded or not smooth enough near there");
    nodes_.push_back(next);
  }
}

std::array<double, kMaxInternal> FloorInternal::at(double t) const {
  const Node& first = nodes_.front();
  if (!(t > first.t)) return first.z;
  extend(t);
  // The last accepted step's start at or before t.
  const auto after = std::upper_bound(nodes_.begin(), nodes_.end(), t,
                                      [](double x, const Node& node) { return x < node.t; });
  const Node& from = *(after - 1);
  if (from.t == t) return from.z;
  GslErrorsAsStatus quiet;
  std::array<double, kMaxInternal> z = from.z, error{};
  gsl_odeiv2_step_reset(system_.rk().dense);
  const int status = gsl_odeiv2_step_apply(system_.rk().dense, from.t, t - from.t, z.data(),
                                           error.data(), nullptr, nullptr, &system_.rk().sys);
  system_.rk().rethrow();
  if (status != GSL_SUCCESS) return after != nodes_.end() ? after->z : from.z;
  return z;
}

void FloorInternal::forget_before(double t) const {
  const auto after = std::upper_bound(nodes_.begin(), nodes_.end(), t,
                                      [](double x, const Node& node) { return x < node.t; });
  if (after - nodes_.begin() > 1) nodes_.erase(nodes_.begin(), after - 1);
}

}  // namespace impact
