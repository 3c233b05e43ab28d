// The internal variables of a particle on the floor (at rest, or chattering towards it), for the
// method event_driven (ode_flight.hpp): the state is (phi, 0), so z' = g(t, phi, 0, z), integrated
// by GSL odeiv2 rk8pd with the flights' tolerances from the time the particle reached the floor.
// z at any t past that time is one rk8pd step from the last accepted step's start at or before t
// (the dense output of ode_flight.hpp), so the lift-off scan and the impulse of a rest, which
// evaluate f(t, phi, 0, z(t)) back and forth, see one smooth z. The accepted steps behind the
// track's time are dropped as it passes them (forget_before), so a long rest keeps O(1) of them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "impact/forces/internal.hpp"
#include "impact/model/model.hpp"
#include "impact/references/rk8pd.hpp"

namespace impact {

// On the floor, z' = g(t, phi, 0, z).
struct FloorRhs {
  int operator()(double t, const double y[], double dydt[]) const;

  InternalRates rates;
  double phi;
};

class FloorInternal {
 public:
  FloorInternal(const Model& model, double rtol, double atol, double max_step);

  // On the floor from t with z.
  void start(double t, const std::array<double, kMaxInternal>& z);
  // The time the particle reached the floor (start's t).
  double origin() const { return origin_; }
  // z at t >= origin(); std::runtime_error when rk8pd cannot take a step (a rate that is not
  // finite or not smooth), naming t.
  std::array<double, kMaxInternal> at(double t) const;
  // The accepted steps before t are no longer needed (t no later than any t asked for next).
  void forget_before(double t) const;

 private:
  struct Node {
    double t;
    std::array<double, kMaxInternal> z;
  };
  void extend(double t) const;

  OdeSystem<FloorRhs> system_;
  double max_step_;
  double origin_ = 0;
  mutable std::vector<Node> nodes_;
};

}  // namespace impact
