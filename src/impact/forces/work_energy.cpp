#include "impact/forces/work_energy.hpp"

namespace impact {

WorkEnergy::WorkEnergy(const Model& model, const State& initial, double h, bool follows_motion)
    : force_(model),
      h_(h),
      constant_(force_.constant()),
      follows_motion_(follows_motion),
      start_(0.0),
      initial_kinetic_(0.5 * initial.v * initial.v),
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

double WorkEnergy::energy(const State& s) const {
  if (constant_) return impact::energy(force_.model(), s);
  if (follows_motion_) return initial_kinetic_ - start_ + impacts_;
  return 0.5 * s.v * s.v - start_ - work_;
}

double WorkEnergy::work() const {
  if (follows_motion_) return 0.5 * last_.v * last_.v - initial_kinetic_ - impacts_;
  return work_;
}

double initial_energy(const Model& model, const State& initial) {
  if (constant_force(model)) return energy(model, initial);
  return 0.5 * initial.v * initial.v - ForceFunction(model).at(0.0, initial) * initial.u;
}

}  // namespace impact
