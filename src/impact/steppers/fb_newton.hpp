// The step (4-1)-(4-3) posed as the smoothed Fischer-Burmeister equation (5-3),
// F_eps(a, b) = a + b - sqrt(a^2 + b^2 + eps) = 0 with a = u^{l+1} - phi and b = N^l,
// solved for u^{l+1} with Newton's method.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "impact/forces/free_flight.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/loop/repeats.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/methods/method_params.hpp"
#include "impact/model/model.hpp"
#include "impact/model/restitution.hpp"

namespace impact {

class FbNewton {
 public:
  FbNewton(const Model& model, double h, const FbNewtonParams& params)
      : FbNewton(model, contact_law(model, MethodParams(params)), h, params) {}
  // `law`: contact_law(model, params) (capabilities.hpp), computed once by make_stepper.
  FbNewton(const Model& model, const ContactLaw& law, double h, const FbNewtonParams& params)
      : model_(model),
        h_(h),
        params_(params),
        sqrt_eps_(std::sqrt(params.epsilon)),
        restitution_(restitution_rule(law)),
        flight_(model, h) {}

  // Works in gap coordinates (u - phi, v) from here on, see do_step.
  void initialize(const State& s, std::int64_t l);
  StepInfo do_step(State& s, std::int64_t l);

  // Why the last step did not converge: the residual it reached, for simulate()'s message.
  std::string failure_reason() const;

  // Repeating steps (repeats.hpp), under a constant force: the steps after a contact step depend
  // on the state it ended in alone (the next free flight starts from it).
  std::int64_t repeat_period() const { return repeats_.period(); }
  void skip_steps(std::int64_t n) {
    repeats_.skip(n);
    flight_.start(repeats_.last_contact() + 1, repeats_.last_state());
  }

 private:
  Model model_;
  double h_;
  FbNewtonParams params_;
  double sqrt_eps_;              // the velocity scale of the smoothing, see step()
  RestitutionRule restitution_;  // the contact law (contact_law.hpp) as restitution.hpp reads it
  SchemeFlight flight_;          // in gap coordinates (u - phi, v), see do_step()
  // The state at t_l in gap coordinates as the last step computed it (the caller's u is
  // phi + gap, rounded).
  State gap_;
  RepeatWatch repeats_;  // watches the contact steps under a constant force
  // The last Newton solve, for failure_reason().
  double residual_ = 0, threshold_ = 0, force_ = 0;
  int iterations_ = 0;
};

}  // namespace impact
