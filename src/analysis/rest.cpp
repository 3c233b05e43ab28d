#include "analysis/rest.hpp"

#include <cmath>
#include <stdexcept>

#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"

namespace impact {

std::vector<Sample> record(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene);
  std::vector<Sample> samples;
  samples.reserve(static_cast<std::size_t>(scene.grid.steps) + 1);
  simulate(
      stepper, scene.initial, scene.grid,
      [&](std::int64_t l, const State& s, const StepInfo& info) {
        samples.push_back({scene.grid.t(l), s.u, s.v, scheme_force(info), energy(scene.model, s)});
      });
  return samples;
}

ChannelDifference max_difference(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  if (a.size() != b.size())
    throw std::invalid_argument("max_difference: runs of different lengths");
  ChannelDifference d;
  for (std::size_t l = 0; l < a.size(); ++l) {
    if (a[l].t != b[l].t) throw std::invalid_argument("max_difference: different time grids");
    d.u = std::fmax(d.u, std::fabs(a[l].u - b[l].u));
    d.v = std::fmax(d.v, std::fabs(a[l].v - b[l].v));
    d.N = std::fmax(d.N, std::fabs(a[l].N - b[l].N));
    d.E = std::fmax(d.E, std::fabs(a[l].E - b[l].E));
  }
  return d;
}

RunStats run_stats(const std::vector<Sample>& run, double h) {
  RunStats stats;
  double sum = 0;
  for (const Sample& s : run) {
    stats.energy_drift = std::fmax(stats.energy_drift, std::fabs(s.E - run.front().E));
    sum += s.N;
    if (s.N > stats.peak_N) {
      stats.peak_N = s.N;
      stats.peak_t = s.t;
    }
  }
  stats.impulse = h * sum;
  return stats;
}

void RestObserver::operator()(std::int64_t l, const State& s, const StepInfo& info) {
  const double E = energy(model_, s);
  if (l == 0)
    energy_initial_ = E;
  else
    contacts_.add_step(l - 1, previous_, s, scheme_force(info));
  energy_final_ = E;
  energy_sum_ += E;
  previous_ = s;
}

RestAnalysis RestObserver::result() const {
  RestAnalysis analysis;
  analysis.episodes = contacts_.episodes();
  analysis.energy_initial = energy_initial_;
  analysis.energy_final = energy_final_;
  analysis.energy_mean = energy_sum_ / static_cast<double>(grid_.steps + 1);
  analysis.rest_time = rest_time(contacts_.count(), grid_);
  analysis.impacts = impacts(contacts_.count());
  return analysis;
}

RestAnalysis analyse_rest(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene);
  RestObserver observer(scene.model, scene.grid);
  simulate(stepper, scene.initial, scene.grid, observer);
  return observer.result();
}

}  // namespace impact
