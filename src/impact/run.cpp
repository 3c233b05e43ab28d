#include "impact/run.hpp"

#include <sstream>

namespace impact {

std::string describe_failure(std::int64_t l, double t, const State& s, const StepInfo& info) {
  std::ostringstream msg;
  msg.precision(17);
  msg << "step " << l << " (from t = " << t << "): ";
  if (!info.converged)
    msg << "the solve did not converge after " << info.iterations << " iterations";
  else
    msg << "non-finite result u = " << s.u << ", v = " << s.v << ", N = " << info.contact_force;
  return msg.str();
}

}  // namespace impact
