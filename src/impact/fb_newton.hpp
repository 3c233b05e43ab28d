// The step (4-1)-(4-3) posed as the smoothed Fischer-Burmeister equation (5-3),
// F_eps(a, b) = a + b - sqrt(a^2 + b^2 + eps) = 0 with a = u^{l+1} - phi and b = N^l,
// solved for u^{l+1} with Newton's method.
#pragma once

#include <cstdint>

#include "impact/free_flight.hpp"
#include "impact/model.hpp"

namespace impact {

class MethodParams;

struct FbNewtonParams {
  double epsilon = 1e-15;    // smoothing parameter (paper: 1e-15)
  double tolerance = 1e-15;  // relative residual, see FbNewton::step (paper: 1e-15)
  int max_iterations = 50;
};

class FbNewton {
 public:
  static FbNewtonParams read_params(MethodParams& p);
  FbNewton(const Model& model, double h, const FbNewtonParams& params)
      : model_(model), h_(h), params_(params), flight_(model.f, h) {}

  StepInfo step(State& s, std::int64_t l);

 private:
  Model model_;
  double h_;
  FbNewtonParams params_;
  FreeFlight flight_;
};

}  // namespace impact
