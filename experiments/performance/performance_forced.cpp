#include "performance_forced.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "analysis/experiment.hpp"
#include "analysis/work_precision_reference.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "scene/read_scene.hpp"

namespace impact {
namespace {

const ExperimentContext kSource{IMPACT_SOURCE_DIR, ""};

Scene scene_named(const std::string& experiment, const std::string& name) {
  return load_scene(kSource.scene_path(experiment, name + ".toml"));
}

Scene with_method(Scene scene, std::string_view method) {
  const MethodInfo* info = find_method(method);
  if (!info) throw std::runtime_error("no method " + std::string(method) + " in this build");
  scene.method = info->defaults;
  return scene;
}

const auto kNoOutput = [](std::int64_t, const State&, const StepInfo&) {};

// One run per iteration; the counter is CPU seconds per `units` of the run (steps, impacts).
void register_run(const std::string& name, const Scene& scene, double units,
                  const std::string& counter,
                  void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    for (auto _ : state) {
      AnyStepper stepper = make_stepper(scene);
      RunSummary summary = simulate(stepper, scene.initial, scene.grid, kNoOutput);
      benchmark::DoNotOptimize(summary);
    }
    state.counters[counter] = benchmark::Counter(
        units, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  });
  add_statistics(b, false);
}

void register_steps(const std::string& name, Scene scene, double h,
                    void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  scene.grid = Grid::covering(scene.T, h);
  register_run(name, scene, static_cast<double>(scene.grid.steps), "s_per_step", add_statistics);
}

}  // namespace

void register_forced_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  // `exact` with a harmonic force, per impact: the period-1 orbit of the vibrating table (one
  // impact per second) over 1000 s in one grid step, so that the run is its event tracking alone.
  Scene period1 = with_method(scene_named("work_precision", "table_period1"), "exact");
  Scene long_run = period1;
  long_run.T = 1000.0;
  long_run.grid = Grid{long_run.T, 1};
  const std::int64_t impacts = count_impacts(long_run);
  if (impacts > 0)
    register_run("impacts/exact/table_period1", long_run, static_cast<double>(impacts),
                 "s_per_impact", add_statistics);

  // Sampling an event-driven solution sequentially on a grid of 1e-6 s (1e7 samples over 10 s):
  // the harmonic vibrating table (constant f with COR is performance.cpp's
  // stepper/exact/figure4_cor075), and an expression force (event_driven, 1e6 samples of 1e-5 s).
  register_steps("stepper/exact/table_period1", period1, 1e-6, add_statistics);
  if (find_method("event_driven"))
    register_steps("stepper/event_driven/expression",
                   with_method(scene_named("work_precision", "expression"), "event_driven"), 1e-5,
                   add_statistics);

  // `direct` with a harmonic force against a constant one. On the vibrating table the constant
  // part alone is another motion (the ball bounces to rest), so the paper's scenes are also run
  // with a weak harmonic term added (0.01 m/s^2 at 1 Hz, against |f| = 0 or 9.8: nearly the same
  // motion, through the harmonic code path), beside performance.cpp's stepper/direct/<scene>.
  const Scene table = with_method(scene_named("work_precision", "table_period1"), "direct");
  Scene table_constant = table;
  table_constant.model.harmonic.reset();
  register_steps("stepper/direct/table_period1", table, 1e-6, add_statistics);
  register_steps("stepper/direct/table_period1_constant_f", table_constant, 1e-6, add_statistics);
  for (const auto& [figure, file] : {std::pair{"figure3", "no_cor"}, {"figure4", "cor075"}}) {
    Scene weak = with_method(scene_named(figure, file), "direct");
    weak.model.harmonic = Harmonic{0.01, 6.283185307179586, 0.0};
    register_steps("stepper/direct/" + std::string(figure) + "_" + file + "_harmonic", weak, 1e-6,
                   add_statistics);
  }
}

}  // namespace impact
