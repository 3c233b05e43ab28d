// Normal compliance (Section 5): the Signorini condition replaced by N = c_N max(phi - u, 0), a
// force that pushes up when the particle penetrates the floor. (The paper writes p(u - phi); with
// p(r) = c_N max(r, 0) that would pull on a particle above the floor: see paper_notes/.)
// Integrated with GSL's odeiv2 drivers between grid points t_l = l h.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "impact/model.hpp"

namespace impact {

struct PenaltyParams {
  double stiffness = 1e6;         // c_N
  std::string stepper = "rk8pd";  // GSL odeiv2 stepper name
  double rtol = 1e-10;
  double atol = 1e-12;
  // The ODE steps the whole run may take (a stiff contact with an implicit stepper can need 1e5
  // per grid step, minutes for T = 1); 0: automatic, 1e6 plus 1000 per grid step done.
  std::int64_t max_ode_steps = 0;

  bool operator==(const PenaltyParams&) const = default;
};

// The names PenaltyParams::stepper accepts: every GSL odeiv2 stepper.
std::span<const std::string_view> penalty_stepper_names();

class Penalty {
 public:
  // Throws std::invalid_argument for parameters outside their ranges or an unknown stepper.
  Penalty(const Model& model, double h, const PenaltyParams& params);
  Penalty(Penalty&&) noexcept;
  Penalty& operator=(Penalty&&) noexcept;
  ~Penalty();

  // Starts the ODE driver afresh at (t_l, s): a multistep method's history is dropped.
  void initialize(const State& s, std::int64_t l);
  // Integrates from t_l to t_{l+1}; N^l is the impulse of the compliance force over the step / h,
  // iterations the number of GSL steps taken.
  StepInfo do_step(State& s, std::int64_t l);

  // Why the last step did not converge (the GSL status and where it stopped), for simulate()'s
  // message.
  std::string failure_reason() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace impact
