#include "impact/chain/chain_moreau_jean.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

namespace impact {

ChainMoreauJean::ChainMoreauJean(const Chain& chain, double h, const MoreauJeanParams& params)
    : chain_(chain), h_(h), theta_(params.theta), e_(chain.cor.value_or(1.0)) {
  check_chain(chain);
  if (!(std::isfinite(h) && h > 0))
    throw std::invalid_argument("chain moreau_jean: h = " + std::to_string(h) +
                                " is out of range: finite, > 0");
  if (!(theta_ >= 0 && theta_ <= 1))
    throw std::invalid_argument("chain moreau_jean: theta = " + std::to_string(theta_) +
                                " is out of range: [0, 1]");
  const double c = h * h * theta_ * theta_ * chain.k;
  Eigen::Matrix2d w;
  w << chain.m1 + c, -c, -c, chain.m2 + c;
  w_inverse_ = w.inverse();  // W is symmetric positive definite: M > 0, K >= 0
  delassus_ = w_inverse_(0, 0);
  gap_.setZero();
  v_.setZero();
}

void ChainMoreauJean::initialize(const ChainState& s, std::int64_t) {
  gap_ = s.q.array() - chain_.phi;
  v_ = s.v;
}

StepInfo ChainMoreauJean::do_step(ChainState& s, std::int64_t) {
  // The spring acts on the stretch alone, so the gaps give it without phi's rounding.
  const double spring = chain_.k * (gap_(1) - gap_(0) - chain_.ell);
  const double spring_rate = chain_.k * (v_(1) - v_(0));  // the stretch's rate under K v
  // -h^2 theta (1 - theta) K v^l: the part of theta h F(q^{l+1}) that v^l moves.
  const double carried = h_ * h_ * theta_ * (1 - theta_);
  const Eigen::Vector2d momentum(
      chain_.m1 * v_(0) + h_ * (spring + chain_.m1 * chain_.g) + carried * spring_rate,
      chain_.m2 * v_(1) + h_ * (chain_.m2 * chain_.g - spring) - carried * spring_rate);
  const Eigen::Vector2d v_free = w_inverse_ * momentum;

  // The one particle's law on the constraint velocity x1': its jump is D P.
  StepInfo info;
  double jump_rate = 0;  // D P / h
  moreau_jean_update(gap_(0), v_(0), jump_rate, v_free(0), e_, theta_, h_);
  const double impulse = jump_rate * h_ / delassus_;  // P^{l+1}
  const double v2 = v_free(1) + w_inverse_(1, 0) * impulse;
  gap_(1) += h_ * (theta_ * v2 + (1 - theta_) * v_(1));
  v_(1) = v2;
  info.contact_force = impulse / h_;
  s.q = gap_.array() + chain_.phi;
  s.v = v_;
  return info;
}

}  // namespace impact
