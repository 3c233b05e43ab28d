// What test_schemes.cpp and test_forcing_steppers.cpp share: a run kept in memory, step by step.
#pragma once

#include <cstddef>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/model/model.hpp"

namespace impact::testing {

struct Row {
  State s;
  StepInfo info;
};

// Every state of a run through simulate(), with the StepInfo of the step that ended there.
template <class Stepper>
std::vector<Row> trajectory(Stepper&& stepper, const State& initial, const Grid& grid) {
  std::vector<Row> rows;
  rows.reserve(static_cast<std::size_t>(grid.steps) + 1);
  simulate(stepper, initial, grid, [&](std::int64_t, const State& s, const StepInfo& info) {
    rows.push_back({s, info});
  });
  return rows;
}

}  // namespace impact::testing
