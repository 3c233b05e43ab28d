#include "impact/work_energy.hpp"

namespace impact {

WorkEnergy::WorkEnergy(const Model& model, const State& initial, double h)
    : force_(model),
      h_(h),
      constant_(force_.constant()),
      start_(force_.at(0.0, initial) * initial.u),
      last_(initial) {}

void WorkEnergy::step(std::int64_t l, const State& s) {
  if (constant_) return;
  work_ += (s.u - last_.u) * force_.step_mean(static_cast<double>(l - 1) * h_, h_, last_);
  last_ = s;
}

double WorkEnergy::energy(const State& s) const {
  if (constant_) return impact::energy(force_.model(), s);
  return 0.5 * s.v * s.v - start_ - work_;
}

double initial_energy(const Model& model, const State& initial) {
  if (constant_force(model)) return energy(model, initial);
  return 0.5 * initial.v * initial.v - ForceFunction(model).at(0.0, initial) * initial.u;
}

}  // namespace impact
