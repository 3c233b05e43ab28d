#include "impact/references/internal_floor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "impact/forces/gsl_errors.hpp"
#include "impact/references/rk8pd.hpp"

namespace impact {

// The integrator; on the heap, since the system's params point here.
struct FloorInternal::Gsl : Rk8pd {
  Gsl(const FloorInternal* owner, std::size_t n, double atol, double rtol)
      : Rk8pd(n, atol, rtol, &Gsl::rhs, this), self(owner) {}
  // z' = g(t, phi, 0, z).
  static int rhs(double t, const double y[], double dydt[], void* params) {
    auto* g = static_cast<Gsl*>(params);
    try {
      g->self->rates_.evaluate(t, {g->self->model_.phi, 0.0}, y, dydt);
    } catch (...) {
      return g->failed();
    }
    return GSL_SUCCESS;
  }

  const FloorInternal* self;
};

FloorInternal::FloorInternal(const Model& model, double rtol, double atol, double max_step)
    : model_(model),
      rates_(model),
      rtol_(rtol),
      atol_(atol),
      max_step_(max_step),
      gsl_(std::make_unique<Gsl>(this, rates_.size(), atol, rtol)) {}

FloorInternal::FloorInternal(const FloorInternal& other)
    : model_(other.model_),
      rates_(other.rates_),
      rtol_(other.rtol_),
      atol_(other.atol_),
      max_step_(other.max_step_),
      gsl_(std::make_unique<Gsl>(this, rates_.size(), atol_, rtol_)),
      origin_(other.origin_),
      nodes_(other.nodes_) {
  gsl_->h_next = other.gsl_->h_next;
}

FloorInternal& FloorInternal::operator=(const FloorInternal& other) {
  if (this != &other) *this = FloorInternal(other);
  return *this;
}

// The GSL system points to its owner, so a move rebuilds it for the new one.
FloorInternal::FloorInternal(FloorInternal&& other) noexcept
    : model_(std::move(other.model_)),
      rates_(std::move(other.rates_)),
      rtol_(other.rtol_),
      atol_(other.atol_),
      max_step_(other.max_step_),
      gsl_(std::move(other.gsl_)),
      origin_(other.origin_),
      nodes_(std::move(other.nodes_)) {
  if (gsl_) gsl_->self = this;
}

FloorInternal& FloorInternal::operator=(FloorInternal&& other) noexcept {
  model_ = std::move(other.model_);
  rates_ = std::move(other.rates_);
  rtol_ = other.rtol_;
  atol_ = other.atol_;
  max_step_ = other.max_step_;
  gsl_ = std::move(other.gsl_);
  origin_ = other.origin_;
  nodes_ = std::move(other.nodes_);
  if (gsl_) gsl_->self = this;
  return *this;
}

FloorInternal::~FloorInternal() = default;

void FloorInternal::start(double t, const std::array<double, kMaxInternal>& z) {
  origin_ = t;
  nodes_.assign(1, Node{t, z});
  gsl_odeiv2_evolve_reset(gsl_->evolve);
  gsl_->h_next = max_step_ / 4;
}

// Accepted steps up to past t.
void FloorInternal::extend(double t) const {
  GslErrorsAsStatus quiet;
  const std::size_t n = rates_.size();
  while (nodes_.back().t < t) {
    Node next = nodes_.back();
    const double from = next.t;
    const int status =
        gsl_odeiv2_evolve_apply(gsl_->evolve, gsl_->control, gsl_->step, &gsl_->sys, &next.t,
                                from + max_step_, &gsl_->h_next, next.z.data());
    gsl_->rethrow();
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
  gsl_odeiv2_step_reset(gsl_->dense);
  const int status = gsl_odeiv2_step_apply(gsl_->dense, from.t, t - from.t, z.data(), error.data(),
                                           nullptr, nullptr, &gsl_->sys);
  gsl_->rethrow();
  if (status != GSL_SUCCESS) return after != nodes_.end() ? after->z : from.z;
  return z;
}

void FloorInternal::forget_before(double t) const {
  const auto after = std::upper_bound(nodes_.begin(), nodes_.end(), t,
                                      [](double x, const Node& node) { return x < node.t; });
  if (after - nodes_.begin() > 1) nodes_.erase(nodes_.begin(), after - 1);
}

}  // namespace impact
