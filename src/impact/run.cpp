#include "impact/run.hpp"

#include <sstream>

namespace impact {

void throw_step_failure(std::int64_t l, double t, State s, StepInfo info) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "step " << l << " (from t = " << t << "): ";
  if (!info.converged)
    msg << "the solve did not converge after " << info.iterations << " iterations";
  else
    msg << "non-finite result u = " << s.u << ", v = " << s.v << ", N = " << info.contact_force;
  throw NumericalError(msg.str());
}

}  // namespace impact
