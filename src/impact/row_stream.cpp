#include "impact/row_stream.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace impact {

RowSchedule::RowSchedule(std::int64_t every, std::int64_t last)
    : every_(every > 0 ? every : 1), last_(last) {}

RowStream::RowStream(std::int64_t every, const Grid& grid, RowSink row, std::int64_t check_every,
                     Check check)
    : rows_(every, grid.steps),
      row_(std::move(row)),
      check_(std::move(check)),
      check_every_(check_ && check_every > 0 ? check_every : 0),
      next_check_(check_every_ > 0 ? check_every_ : std::numeric_limits<std::int64_t>::max()) {}

bool RowStream::at(std::int64_t l, const State& s, const StepInfo& info, double force_sum,
                   std::int64_t iteration_sum) {
  return at(l, s, {}, info, force_sum, iteration_sum);
}

bool RowStream::at(std::int64_t l, const StateWithInternal& s, const StepInfo& info,
                   double force_sum, std::int64_t iteration_sum) {
  return at(l, s, s.z, info, force_sum, iteration_sum);
}

bool RowStream::at(std::int64_t l, const State& s, const std::array<double, kMaxInternal>& internal,
                   const StepInfo& info, double force_sum, std::int64_t iteration_sum) {
  bool wrote = false;
  if (l == rows_.next()) {
    OutputRow row{l, s, 0.0, iteration_sum, 0.0, internal};
    // One step: N^{l-1} as the step gave it (bit for bit, -0 included); more: their mean.
    const std::int64_t steps = l - last_row_;
    row.contact_force = steps == 1  ? info.contact_force
                        : steps > 1 ? force_sum / static_cast<double>(steps)
                                    : 0.0;
    row_(row);
    last_row_ = l;
    rows_.advance();
    wrote = true;
  }
  if (l == next_check_) {
    next_check_ = l + check_every_;
    check_(l);
  }
  next_ = std::min(rows_.next(), next_check_);
  return wrote;
}

void watch_step(const StepWatch& watch, std::int64_t l, State s, StepInfo info) {
  watch(l, StateWithInternal{s, {}}, info);
}

void watch_step(const StepWatch& watch, std::int64_t l, StateWithInternal s, StepInfo info) {
  watch(l, s, info);
}

}  // namespace impact
