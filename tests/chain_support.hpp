// What the two-mass chain's tests share (test_chain.cpp, test_chain_rest.cpp).
#pragma once

#include <cmath>
#include <cstdint>

#include "impact/chain/chain.hpp"
#include "impact/chain/chain_moreau_jean.hpp"
#include "impact/chain/chain_reference.hpp"
#include "impact/loop/simulate.hpp"

namespace impact::testing {

// max over the grid of |x - x_ref| (both masses) of Moreau-Jean at step h against the reference.
inline double max_position_error(const Chain& chain, const ChainState& initial, double h,
                                 double T) {
  const Grid grid = Grid::covering(T, h);
  const ChainReference reference(chain, initial, {.t_end = grid.end()});
  ChainMoreauJean stepper(chain, h, MoreauJeanParams{});
  double error = 0;
  simulate(stepper, initial, grid, [&](std::int64_t l, const ChainState& s, const StepInfo&) {
    error = std::fmax(error, (s.q - reference.at(grid.t(l)).q).cwiseAbs().maxCoeff());
  });
  return error;
}

}  // namespace impact::testing
