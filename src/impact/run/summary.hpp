// The summary of one run in O(1) memory, for parameter sweeps (`impact sweep`): no trajectory is
// stored. Contact steps, episodes and rest follow the one rule of contact.hpp; the errors against
// the exact solution are those of error_norms.hpp, from the same run.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

#include "impact/ensemble/ensemble.hpp"
#include "impact/ensemble/summary_lanes.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/model.hpp"
#include "impact/run/bond_events.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/scene.hpp"

namespace impact {

struct PointSummary {
  State final;  // u^n, v^n at T
  // E^n (3-1), v^2/2 - f u, for a constant force; for a time-dependent one, v^2/2 - f(0) u(0) - W
  // (work_energy.hpp), set by summarize() (run_result.hpp); NaN where nothing set it.
  double energy_final = std::numeric_limits<double>::quiet_NaN();
  std::int64_t contact_steps = 0;
  std::int64_t impacts = 0;  // contact episodes before rest (all of them without rest)
  // t_l + floor_crossing(u^l, v^l) for the first contact step l; NaN without contact.
  double first_impact_time = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> rest_time;                    // rest_time() of contact.hpp
  double max_u = 0;                                   // max over l of u^l
  std::int64_t iterations = 0;                        // Newton iterations or ODE steps (RunSummary)
  std::array<double, kMaxInternal> internal_final{};  // the internal variables at T (model.hpp)
  BondFates bonds;  // a bonded model's first debond, capture and escape (bond_events.hpp)
};

PointSummary finish_summary(const SummaryLanes<double>& lanes, const Model& model, const Grid& grid,
                            const State& final, std::int64_t iterations);

// An observer for simulate() that builds the PointSummary as the run streams.
class SummaryObserver {
 public:
  static constexpr bool kStepsLocally = true;  // simulate() keeps the running values in registers

  SummaryObserver(const Model& model, const Grid& grid) : model_(model), grid_(grid) {}

  // St: State, or StateWithInternal (the summary keeps the internal variables at T).
  template <class St>
  void operator()(std::int64_t l, const St& s, const StepInfo& info) {
    if (l == 0)
      start_summary(lanes_, s.u);
    else
      summary_step(lanes_, static_cast<double>(l - 1), model_.phi, previous_.u, previous_.v, s.u,
                   scheme_force(info));
    previous_ = s;
    if constexpr (std::is_same_v<St, StateWithInternal>) internal_ = s.z;
  }

  PointSummary result(const RunSummary& run) const {
    PointSummary summary = finish_summary(lanes_, model_, grid_, previous_, run.iterations);
    summary.internal_final = internal_;
    return summary;
  }

 private:
  Model model_;
  Grid grid_;
  SummaryLanes<double> lanes_;
  State previous_;
  std::array<double, kMaxInternal> internal_{};
};

struct PointOutcome {
  PointSummary summary;
  std::optional<ErrorNorms> errors;  // with against_exact
  double reference_seconds = 0;      // the wall time the reference took (against_exact)
};

// The ensemble kernel that steps the scene's method bit-identically, if there is one: direct with
// its closed-form free flight, and moreau_jean, under a constant force.
struct EnsembleKind {
  EnsembleMethod method;
  double theta;  // moreau_jean's; 0.5 (unused) for direct
};
std::optional<EnsembleKind> ensemble_kind(const Scene& scene);

// Many points on one grid with one ensemble method, stepped together; out[i] is the summary of
// point i, bit-identical to summarize() of its scene, or nullopt where a step gave a non-finite
// value (summarize() then names the step and the reason).
// `instruction_set` picks the ensemble's vector code (Ensemble::use; all give the same bits), empty
// for the widest this processor has. `stop`, when given, is read every check_every steps (the
// ensemble advances in pieces of that many steps, the same bits as in one); once it is set,
// Interrupted is thrown (simulate.hpp). With SummaryDepth::final_state only `final` and
// `energy_final` are computed (the rest keeps PointSummary's defaults), at close to the ensemble's
// own rate.
void summarize_together(const EnsembleKind& kind, const Grid& grid, std::span<const Model> models,
                        std::span<const State> initial, std::span<std::optional<PointSummary>> out,
                        std::string_view instruction_set = {},
                        const std::atomic<bool>* stop = nullptr, std::int64_t check_every = 0,
                        SummaryDepth depth = SummaryDepth::per_step);

}  // namespace impact
