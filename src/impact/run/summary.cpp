#include "impact/run/summary.hpp"

#include <algorithm>
#include <stdexcept>

namespace impact {

PointSummary finish_summary(const SummaryLanes<double>& lanes, const Model& model, const Grid& grid,
                            const State& final, std::int64_t iterations) {
  PointSummary p;
  p.final = final;
  if (constant_force(model)) p.energy_final = energy(model, final);
  p.contact_steps = static_cast<std::int64_t>(lanes.contacts.steps);
  p.impacts = impacts(lanes.contacts);
  if (lanes.contacts.episodes > 0) {
    const std::int64_t l = static_cast<std::int64_t>(lanes.first_l);
    p.first_impact_time = grid.t(l) + floor_crossing(model, {lanes.first_u, lanes.first_v});
  }
  p.rest_time = rest_time(lanes.contacts, grid);
  p.max_u = lanes.max_u;
  p.iterations = iterations;
  return p;
}

std::optional<EnsembleKind> ensemble_kind(const Scene& scene) {
  // The ensemble takes a constant f only, and no internal variables or bonds (their steppers
  // carry z).
  if (!constant_force(scene.model) || !scene.model.internal.empty() || bonded(scene.model))
    return std::nullopt;
  if (const auto* direct = std::get_if<DirectParams>(&scene.method))
    if (direct->free_flight == FreeFlightForm::closed_form)
      return EnsembleKind{EnsembleMethod::direct, 0.5};
  if (const auto* mj = std::get_if<MoreauJeanParams>(&scene.method))
    return EnsembleKind{EnsembleMethod::moreau_jean, mj->theta};
  return std::nullopt;
}

void summarize_together(const EnsembleKind& kind, const Grid& grid, std::span<const Model> models,
                        std::span<const State> initial, std::span<std::optional<PointSummary>> out,
                        std::string_view instruction_set, const std::atomic<bool>* stop,
                        std::int64_t check_every, SummaryDepth depth) {
  if (out.size() != models.size())
    throw std::invalid_argument("summarize_together: as many outputs as models are needed");
  Ensemble ensemble(kind.method, models, initial, grid.h, kind.theta);
  if (!instruction_set.empty()) ensemble.use(instruction_set);
  ensemble.keep_summary(depth);
  if (stop && check_every > 0) {
    while (ensemble.steps_done() < grid.steps) {
      ensemble.advance(std::min(check_every, grid.steps - ensemble.steps_done()));
      if (stop->load(std::memory_order_relaxed)) throw Interrupted{};
    }
  } else {
    ensemble.advance(grid.steps);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto index = static_cast<Eigen::Index>(i);
    if (ensemble.failed(index)) {
      out[i].reset();
    } else if (depth == SummaryDepth::per_step) {
      out[i] = finish_summary(ensemble.summary(index), models[i], grid, ensemble.state(index), 0);
    } else {
      PointSummary& p = out[i].emplace();
      p.final = ensemble.state(index);
      p.energy_final = energy(models[i], p.final);  // the ensemble's force is constant
    }
  }
}

}  // namespace impact
