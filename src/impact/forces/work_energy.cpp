#include "impact/forces/work_energy.hpp"

namespace impact {

WorkEnergy::WorkEnergy(const Model& model, const State& initial, double h, bool follows_motion)
    : force_(model),
      h_(h),
      constant_(force_.constant()),
      follows_motion_(follows_motion),
      start_(0.0),
      initial_kinetic_(0.5 * initial.v * initial.v),
      bonds_(bonded(model) ? model.bonding : std::nullopt),
      phi_(model.phi),
      initial_bonds_(bonds_ ? adhesive_energy(*bonds_, bonds_->beta0, initial.u - model.phi) : 0.0),
      z0_(with_internal(model, initial).z),
      last_(with_internal(model, initial)) {
  force_.set_internal(z0_);
  start_ = force_.at(0.0, initial) * initial.u;
}

void WorkEnergy::step(std::int64_t l, const StateWithInternal& s) {
  if (constant_) return;
  if (!follows_motion_) {
    force_.set_internal(last_.z);
    work_ += (s.u - last_.u) * force_.step_mean(static_cast<double>(l - 1) * h_, h_, last_);
  }
  last_ = s;
}

void WorkEnergy::event(const Event& e) {
  if (e.kind == EventKind::impact)
    impacts_ += 0.5 * e.v_after * e.v_after - 0.5 * e.v_before * e.v_before;
}

double WorkEnergy::energy(const StateWithInternal& s) const {
  if (constant_) return impact::energy(force_.model(), s);
  if (follows_motion_) {
    if (!bonds_) return initial_kinetic_ - start_ + impacts_;
    return initial_kinetic_ - start_ + initial_bonds_ + impacts_ - s.z[kBondEnergy];
  }
  if (!bonds_) return 0.5 * s.v * s.v - start_ - work_;
  return 0.5 * s.v * s.v - start_ - work_ +
         adhesive_energy(*bonds_, s.z[kBondFraction], s.u - phi_);
}

double initial_energy(const Model& model, const State& initial) {
  if (constant_force(model)) return energy(model, initial);
  return 0.5 * initial.v * initial.v - ForceFunction(model).at(0.0, initial) * initial.u;
}

}  // namespace impact
