// One row of a run's output, as plain data: what the CSV writer, the channels and the row stream
// (row_stream.hpp, which decimates the steps into rows) share.
#pragma once

#include <array>
#include <cstdint>

#include "impact/model/model.hpp"

namespace impact {

// One written row: the state at t_l = l h and what the steps since the previous row carried.
struct OutputRow {
  std::int64_t l = 0;
  State state;
  double contact_force = 0.0;   // the mean of N^j over those steps (0 at l = 0)
  double scheme_force = 0.0;    // the mean of their scheme_force (model.hpp), where asked for
  std::int64_t iterations = 0;  // the sum of their iterations
  double energy = 0.0;          // E at t_l where the output asks for it (run_scene.hpp)
  std::array<double, kMaxInternal> internal{};  // the internal variables at t_l (model.hpp)
};

}  // namespace impact
