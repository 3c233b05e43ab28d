#include "impact/run/bond_events.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact {

BondEvents::BondEvents(const Model& model, double h, EventSink sink)
    : bonds_(model.bonding.value_or(Bonding{})),
      phi_(model.phi),
      h_(h),
      force_free_(constant_force(model) && model.f == 0.0),
      sink_(std::move(sink)) {
  if (!bonded(model)) throw std::invalid_argument("BondEvents: the model has no bonding field");
}

// An event at t in the step from before_ (t_{l-1}) to s (t_l), with beta and D at t.
void BondEvents::add(double t, EventKind kind, double v_before, double v_after,
                     const StateWithInternal& s) {
  Event e{t, kind, v_before, v_after, {}};
  const double w = std::clamp((t - static_cast<double>(l_ - 1) * h_) / h_, 0.0, 1.0);
  for (const std::size_t i : {kBondFraction, kBondEnergy})
    e.internal[i] = before_.z[i] + w * (s.z[i] - before_.z[i]);
  double& first = kind == EventKind::debond    ? fates_.debond
                  : kind == EventKind::capture ? fates_.capture
                                               : fates_.escape;
  if (std::isnan(first)) first = t;
  held_.push_back(e);
}

void BondEvents::operator()(std::int64_t l, const StateWithInternal& s) {
  l_ = l;
  const double beta = s.z[kBondFraction], gap = s.u - phi_;
  if (l == 0) {
    broken_ = beta <= bonds_.debond_below;
  } else {
    const double t0 = static_cast<double>(l - 1) * h_;
    const double beta0 = before_.z[kBondFraction];
    if (!broken_ && beta <= bonds_.debond_below) {
      broken_ = true;
      const double w = std::clamp((beta0 - bonds_.debond_below) / (beta0 - beta), 0.0, 1.0);
      const double v = before_.v + w * (s.v - before_.v);
      add(t0 + w * h_, EventKind::debond, v, v, s);
    }
    if (rising_ && !escaped_ && s.v <= 0.0) {
      rising_ = false;
      add(t0 + h_ * std::clamp(before_.v / (before_.v - s.v), 0.0, 1.0), EventKind::capture, 0.0,
          0.0, s);
    }
  }
  if (!escaped_ && gap > 0.0 && s.v > 0.0) {
    rising_ = true;
    if (force_free_ && never_returns(bonds_, beta, gap, s.v)) {
      escaped_ = true;
      add(static_cast<double>(l) * h_, EventKind::escape, s.v, s.v, s);
    }
  }
  before_ = s;
  if (held_.empty()) return;
  std::stable_sort(held_.begin(), held_.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });
  if (sink_)
    for (const Event& e : held_) sink_(e);
  held_.clear();
}

}  // namespace impact
