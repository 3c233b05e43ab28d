#include "impact/run/row_stream.hpp"

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

bool RowStream::at(std::int64_t l, const State& s, const StepInfo& info, const Sums& sums) {
  return at(l, s, {}, info, sums);
}

bool RowStream::at(std::int64_t l, const StateWithInternal& s, const StepInfo& info,
                   const Sums& sums) {
  return at(l, s, s.z, info, sums);
}

bool RowStream::at(std::int64_t l, const State& s, const std::array<double, kMaxInternal>& internal,
                   const StepInfo& info, const Sums& sums) {
  bool wrote = false;
  if (l == rows_.next()) {
    OutputRow row{l, s, 0.0, 0.0, sums.iterations, 0.0, internal};
    // One step: N^{l-1} as the step gave it (bit for bit, -0 included); more: their mean.
    const std::int64_t steps = l - last_row_;
    const auto mean = [&](double one, double sum) {
      return steps == 1 ? one : steps > 1 ? sum / static_cast<double>(steps) : 0.0;
    };
    row.contact_force = mean(info.contact_force, sums.force);
    row.scheme_force = mean(scheme_force(info), sums.scheme);
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
