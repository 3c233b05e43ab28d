// The paper's scheme (4-1)-(4-3), solved in closed form at each step as in (5-1).
#pragma once

#include <cstdint>

#include "impact/free_flight.hpp"
#include "impact/model.hpp"
#include "impact/restitution.hpp"

namespace impact {

class MethodParams;

struct DirectParams {};

class Direct {
 public:
  static DirectParams read_params(MethodParams&) { return {}; }
  Direct(const Model& model, double h, const DirectParams&)
      : model_(model), h_(h), flight_(model.f, h) {}

  StepInfo step(State& s, std::int64_t l) {
    const double phi = model_.phi, h = h_;
    // (5-1) with N^l = 0: where the particle would be if the floor were not there.
    const State free = flight_.predict(s, l);
    StepInfo info;
    if (free.u > phi) {
      s = free;
      flight_.accept(l + 1, s, true);
      return info;
    }
    // (4-3) forces u^{l+1} = phi; (5-1) solved for N^l,
    // N^l = (2/h)((phi - u^l)/h - v^l) - f = (2/h^2)(phi - u_free) >= 0.
    info.contact_force = 2 / (h * h) * (phi - free.u);
    const double v_scheme = free.v + h * info.contact_force;  // (4-1), equal to (4-2) here
    s.v = velocity_after_contact(model_, s.v, v_scheme);
    s.u = phi;
    flight_.accept(l + 1, s, false);
    return info;
  }

 private:
  Model model_;
  double h_;
  FreeFlight flight_;
};

}  // namespace impact
