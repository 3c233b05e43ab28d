// Normal compliance (Section 5): the Signorini condition replaced by N = c_N max(phi - u, 0), a
// force that pushes up when the particle penetrates the floor. (The paper writes p(u - phi); with
// p(r) = c_N max(r, 0) that would pull on a particle above the floor: see paper_notes/.)
// Integrated with GSL's odeiv2 drivers between grid points t_l = l h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "impact/methods/method_params.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"

namespace impact {

class Penalty {
 public:
  // Throws std::invalid_argument for parameters outside their ranges or an unknown stepper.
  Penalty(const Model& model, double h, const PenaltyParams& params);
  // `law`: contact_law(model, params) (capabilities.hpp), a ComplianceLaw, computed once by
  // make_stepper.
  Penalty(const Model& model, const ContactLaw& law, double h, const PenaltyParams& params);
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
