#include "impact/loop/simulate.hpp"

#include <sstream>

namespace impact {

void throw_step_failure(std::int64_t l, double t, State s, StepInfo info) {
  throw_step_failure(l, t, s, info, std::string());
}

void throw_step_failure(std::int64_t l, double t, State s, StepInfo info,
                        const std::string& detail) {
  std::ostringstream state;
  state.precision(17);
  state << "u = " << s.u << ", v = " << s.v;
  throw_step_failure(l, t, state.str(), info, detail);
}

void throw_step_failure(std::int64_t l, double t, const std::string& state, StepInfo info,
                        const std::string& detail) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "step " << l << " (from t = " << t << "): ";
  if (info.converged)
    msg << "non-finite result " << state << ", N = " << info.contact_force
        << (detail.empty() ? "" : ": ") << detail;
  else if (info.iterations > 0)  // an iterative solve: how far it got, then the stepper's account
    msg << "the solve did not converge after " << info.iterations << " iterations"
        << (detail.empty() ? "" : ": ") << detail;
  else  // a stepper that does not iterate (exact, event_driven) says what stopped it
    msg << (detail.empty() ? "the solve did not converge" : detail);
  throw NumericalError(msg.str(), info.converged);
}

}  // namespace impact
