// Moreau-Jean time-stepping (velocity level, theta-method, Newton's impact law), as in Siconos's
// MoreauJeanOSI with a one-contact LCP, for comparison with the paper's position-level scheme:
//   v^{l+1} = v^l + h f + P^{l+1},  u^{l+1} = u^l + h (theta v^{l+1} + (1 - theta) v^l),
//   if the contact is active (u^l - phi + gamma h v^l <= 0, gamma = 1/2):
//     0 <= v^{l+1} + e v^l  ⟂  P^{l+1} >= 0,
// with e = COR, or e = 1 when the scene gives none (the elastic limit of the exact reference).
// The position is not projected, so u may dip below phi by O(h |v|).
#pragma once

#include <cstdint>

#include "impact/model.hpp"

namespace impact {

class MethodParams;

struct MoreauJeanParams {
  double theta = 0.5;
};

class MoreauJean {
 public:
  static MoreauJeanParams read_params(MethodParams& p);
  MoreauJean(const Model& model, double h, const MoreauJeanParams& params)
      : model_(model), h_(h), theta_(params.theta), e_(model.cor.value_or(1.0)) {}

  StepInfo step(State& s, std::int64_t) const {
    const double h = h_;
    const double v_free = s.v + h * model_.f;
    double impulse = 0;
    if (s.u - model_.phi + 0.5 * h * s.v <= 0) {
      // The one-contact LCP in closed form: the smallest impulse that makes v^{l+1} >= -e v^l.
      const double target = -e_ * s.v;
      if (v_free < target) impulse = target - v_free;
    }
    const double v_next = v_free + impulse;
    s.u += h * (theta_ * v_next + (1 - theta_) * s.v);
    s.v = v_next;
    StepInfo info;
    info.contact_force = impulse / h;
    return info;
  }

 private:
  Model model_;
  double h_;
  double theta_;
  double e_;
};

}  // namespace impact
