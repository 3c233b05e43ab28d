#include "impact/moreau_jean.hpp"

#include "impact/scene.hpp"

namespace impact {

MoreauJeanParams MoreauJean::read_params(MethodParams& p) {
  MoreauJeanParams params;
  params.theta = p.number("theta", params.theta, 0.0, 1.0);
  return params;
}

}  // namespace impact
