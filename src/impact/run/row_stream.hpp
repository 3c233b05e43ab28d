// Decimated output of a run (output.every = k): a row at t_0, at every k-th step and at the last
// step. A row stands for the steps since the previous row: its N is their mean contact force, so
// that the row's interval times N is the contact impulse delivered in it and the rows keep every
// impulse at any k (h * sum N^l = v^n - v^0 - int f, (4-9)); its iterations are their sum, so that
// the rows add up to the run's total. State channels (u, v, E) are those of the row's own step.
//
// The step loop sees a RowTap: one comparison per step (and two additions when N or the
// iterations are written), so that it keeps its state in registers (simulate.hpp); the rows, and
// the periodic checks a long run makes (a full disk, progress), are handled out of line by
// RowStream, at the next step where one of them is due.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "impact/loop/simulate.hpp"
#include "impact/model/model.hpp"
#include "impact/output/row.hpp"

namespace impact {

// Which steps get a row: l = 0, every, 2 every, ... and always the last step.
class RowSchedule {
 public:
  RowSchedule(std::int64_t every, std::int64_t last);
  // The index of the next row (past the last one: last + 1, which no step reaches).
  std::int64_t next() const { return next_; }
  // Moves past the row at next().
  void advance() {
    next_ = next_ == last_ ? last_ + 1 : (last_ - next_ > every_ ? next_ + every_ : last_);
  }

 private:
  std::int64_t every_, last_, next_ = 0;
};

// The out-of-line part of a run's output: rows by RowSchedule, and a check every `check_every`
// steps (at check_every, 2 check_every, ...).
class RowStream {
 public:
  using RowSink = std::function<void(const OutputRow&)>;
  using Check = std::function<void(std::int64_t l)>;
  RowStream(std::int64_t every, const Grid& grid, RowSink row, std::int64_t check_every = 0,
            Check check = {});

  // The sums over the steps since the last row (those of step l included) of N^j, of the scheme's
  // force and of the iterations.
  struct Sums {
    double force = 0.0, scheme = 0.0;
    std::int64_t iterations = 0;
  };

  // The next step at which at() must be called.
  std::int64_t next() const { return next_; }
  // Step l == next() with the state there, the StepInfo of the step that ended there and the sums
  // since the last row; returns whether a row was written (the sums then start again from 0).
  bool at(std::int64_t l, const State& s, const StepInfo& info, const Sums& sums);
  // The same for a state with internal variables: the row carries them.
  bool at(std::int64_t l, const StateWithInternal& s, const StepInfo& info, const Sums& sums);

 private:
  bool at(std::int64_t l, const State& s, const std::array<double, kMaxInternal>& internal,
          const StepInfo& info, const Sums& sums);

  RowSchedule rows_;
  RowSink row_;
  Check check_;
  std::int64_t check_every_, next_check_, last_row_ = 0, next_ = 0;
};

// The observer a step loop sees (simulate()): kSums adds N^l and the iterations of every step,
// which the rows need when they carry N or the iterations, kScheme the scheme's force (the channel
// N_scheme). A step that writes no row costs those additions and one comparison.
template <bool kSums, bool kScheme = false>
class RowTap {
 public:
  static constexpr bool kStepsLocally = true;  // simulate() keeps the running values in registers

  explicit RowTap(RowStream& stream) : stream_(&stream) { running_.next = stream.next(); }

  // St: State, or StateWithInternal. Inlined, as the step loop's own code must be: a call that
  // receives the tap's address keeps its sums in memory, one store-to-load round trip a step
  // (measured on an AMD EPYC family 26 model 2: 3.5 instead of 1.2 ns a step at rest).
  template <class St>
  [[gnu::always_inline]] void operator()(std::int64_t l, const St& s, const StepInfo& info) {
    if constexpr (kSums) {
      running_.force += info.contact_force;
      running_.iterations += info.iterations;
    }
    if constexpr (kScheme) running_.scheme += scheme_force(info);
    if (l == running_.next) [[unlikely]]
      running_ = due(stream_, l, s, info, running_);
  }

 private:
  // The sums since the last row and the next step that needs the stream.
  struct Running {
    double force = 0.0, scheme = 0.0;
    std::int64_t iterations = 0;
    std::int64_t next = 0;
  };

  // Out of line, on copies, returning the running values: none of them is live across the call,
  // so that the common path keeps them in registers.
  template <class St>
  [[gnu::noinline]] static Running due(RowStream* stream, std::int64_t l, St s, StepInfo info,
                                       Running running) {
    if (stream->at(l, s, info, {running.force, running.scheme, running.iterations})) running = {};
    running.next = stream->next();
    return running;
  }

  RowStream* stream_;
  Running running_;
};

// Runs `stepper` over the grid, streaming its rows to `stream`; `watch`, when given, sees every
// step first (the errors against a reference, the work of f(t), a time-stepper's events), out of
// line. A watch sees the internal variables of a
// stepper that follows them (zero for the others); a function of State can be one.
using StepWatch =
    std::function<void(std::int64_t l, const StateWithInternal& s, const StepInfo& info)>;
// watch(l, s, info), out of line on copies.
[[gnu::noinline]] void watch_step(const StepWatch& watch, std::int64_t l, State s, StepInfo info);
[[gnu::noinline]] void watch_step(const StepWatch& watch, std::int64_t l, StateWithInternal s,
                                  StepInfo info);

// `sums`: the rows carry N or the iterations; `scheme`: the channel N_scheme.
template <class S>
RunSummary simulate_rows(S& stepper, const State& initial, const Grid& grid, RowStream& stream,
                         bool sums, const StepWatch& watch, bool scheme = false) {
  const auto with = [&]<bool kSums, bool kScheme>() {
    RowTap<kSums, kScheme> tap(stream);
    if (!watch) return simulate(stepper, initial, grid, tap);
    return simulate(stepper, initial, grid,
                    [&](std::int64_t l, const auto& s, const StepInfo& info) {
                      watch_step(watch, l, s, info);
                      tap(l, s, info);
                    });
  };
  if (scheme) return with.template operator()<true, true>();
  return sums ? with.template operator()<true, false>() : with.template operator()<false, false>();
}

}  // namespace impact
