// Moreau-Jean time-stepping (moreau_jean.hpp) for the two-mass chain (chain.hpp): the theta-method
// on the linear flight dynamics, M q'' = F(q) = -K q + b, and the one-contact LCP on the lower
// mass's impulse P^{l+1}:
//   W v^{l+1} = M v^l + h F(q^l) - h^2 theta (1 - theta) K v^l + (P^{l+1}, 0),
//   W = M + h^2 theta^2 K,  q^{l+1} = q^l + h (theta v^{l+1} + (1 - theta) v^l),
//   if u^l - phi + h x1'^l / 2 <= 0:  0 <= x1'^{l+1} + e x1'^l  ⟂  P^{l+1} >= 0,
// which is the theta-rule theta F(q^{l+1}) + (1 - theta) F(q^l) solved for v^{l+1}. The LCP is
// 1x1 on the constraint velocity x1' = v_free_1 + D P with the Delassus value D = (W^-1)_11 > 0,
// so it is the one particle's, solved by the same law (moreau_jean_update) on x1' alone: the
// velocity jump it gives is D P. k = 0 gives W = M, D = 1/m1: the lower mass steps as
// MoreauJean's particle. The positions are kept as gaps q - phi (moreau_jean.hpp says why).
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "impact/chain/chain.hpp"
#include "impact/model/model.hpp"
#include "impact/steppers/moreau_jean.hpp"

namespace impact {

class ChainMoreauJean {
 public:
  using StateType = ChainState;

  // Throws std::invalid_argument for bad chain data (check_chain), h not finite and > 0 or theta
  // outside [0, 1].
  ChainMoreauJean(const Chain& chain, double h, const MoreauJeanParams& params);

  void initialize(const ChainState& s, std::int64_t l);
  // contact_force = P^{l+1} / h, a force (m1 times the one particle's N^l); iterations = 0 (the
  // LCP is solved in closed form).
  StepInfo do_step(ChainState& s, std::int64_t l);

 private:
  Chain chain_;
  double h_, theta_, e_;
  Eigen::Matrix2d w_inverse_;  // W^-1
  double delassus_;            // (W^-1)_11
  Eigen::Vector2d gap_;        // q^l - phi
  Eigen::Vector2d v_;          // v^l
};

}  // namespace impact
