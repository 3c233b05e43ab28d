#include "performance_phases.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "analysis/experiment.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/direct.hpp"
#include "performance_cli.hpp"
#include "scene/read_scene.hpp"

namespace impact {
namespace {

const ExperimentContext kSource{IMPACT_SOURCE_DIR, ""};

struct Phase {
  const char* name;
  const char* experiment;
  const char* scene;
  double T;             // the length of the phase's run
  bool after_ten_secs;  // from the method's state at t = 10 s, else from the scene's initial state
};
constexpr Phase kPhases[] = {{"free_flight", "figure3", "no_cor", 10.0, false},
                             {"bouncing", "figure4", "cor075", 6.0, false},
                             {"chatter", "figure4", "no_cor", 10.0, true},
                             {"rest", "figure4", "cor075", 10.0, true}};

struct Method {
  const char* name;
  std::int64_t steps;
};
constexpr Method kMethods[] = {
    {"direct", 100'000'000}, {"moreau_jean", 100'000'000}, {"fb_newton", 10'000'000}};

std::string scene_file(const Phase& phase) {
  return kSource.scene_path(phase.experiment, std::string(phase.scene) + ".toml");
}

// The phase's run for this method with `steps` steps: the scene, its method, h = T / steps, and
// the initial state (see performance_phases.hpp).
Scene phase_scene(const Phase& phase, const Method& method) {
  Scene scene = load_scene(scene_file(phase));
  scene.method = find_method(method.name)->defaults;
  const double h = phase.T / static_cast<double>(method.steps);
  if (phase.after_ten_secs) {
    scene.grid = Grid::covering(10.0, h);
    AnyStepper stepper = make_stepper(scene);
    std::optional<State> after_contact;
    simulate(stepper, scene.initial, scene.grid,
             [&](std::int64_t, const State& s, const StepInfo& info) {
               if (info.contact_force > 0) after_contact = s;
             });
    // moreau_jean does not project: it rests slightly below the floor, where a scene may not
    // start, so its phase starts on the floor with the state's v and settles within a few steps.
    if (after_contact)
      scene.initial = {std::fmax(after_contact->u, scene.model.phi), after_contact->v};
  }
  scene.T = phase.T;
  scene.grid = Grid::covering(phase.T, h);
  return scene;
}

std::string name_of(const char* kind, const Method& method, const Phase& phase) {
  return std::string(kind) + "/" + method.name + "/" + phase.name;
}

const auto kPerStep = benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert;

void register_simulate(const std::string& name, const Scene& scene,
                       void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& state) {
    RunSummary summary;
    for (auto _ : state) {
      AnyStepper stepper = make_stepper(scene);
      summary = simulate(stepper, scene.initial, scene.grid,
                         [](std::int64_t, const State&, const StepInfo&) {});
      benchmark::DoNotOptimize(summary);
    }
    const auto steps = static_cast<double>(scene.grid.steps);
    state.counters["s_per_step"] = benchmark::Counter(steps, kPerStep);
    state.counters["contact_fraction"] = static_cast<double>(summary.contact_steps) / steps;
  });
  add_statistics(b, false);
}

// The scheme (5-1) alone on one particle: the kernel that Direct and the ensemble step.
void register_bare(const std::string& name, const Scene& scene,
                   void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [scene](benchmark::State& state) {
    const Model& m = scene.model;
    const double cor = m.cor.value_or(0.0);
    const std::int64_t fixed_point = m.cor ? restitution_fixed_point(cor) : -1;
    for (auto _ : state) {
      DirectLanes<double> lanes;
      lanes.anchor_gap = lanes.gap = scene.initial.u - m.phi;
      lanes.anchor_v = lanes.v = scene.initial.v;
      for (std::int64_t l = 0; l < scene.grid.steps; ++l)
        direct_step(lanes, m.f, cor, m.cor.has_value(), fixed_point, scene.grid.h);
      benchmark::DoNotOptimize(lanes);
    }
    state.counters["s_per_step"] =
        benchmark::Counter(static_cast<double>(scene.grid.steps), kPerStep);
  });
  add_statistics(b, false);
}

void register_cli(const std::string& name, const Scene& scene, const Phase& phase,
                  const Method& method, const std::string& cli, const std::string& out_dir,
                  void (*add_statistics)(benchmark::internal::Benchmark*, bool)) {
  const std::vector<std::string> args{cli,
                                      "run",
                                      scene_file(phase),
                                      "--set",
                                      std::string("method.name=") + method.name,
                                      "--set",
                                      "time.T=" + round_trip(scene.T),
                                      "--set",
                                      "time.h=" + round_trip(scene.grid.h),
                                      "--set",
                                      "initial.u0=" + round_trip(scene.initial.u),
                                      "--set",
                                      "initial.v0=" + round_trip(scene.initial.v),
                                      "--set",
                                      "output.every=" + std::to_string(scene.grid.steps / 10000),
                                      "--quiet",
                                      "--out",
                                      out_dir + "/cli_phase.csv"};
  register_cli_run(name, args, scene.grid.steps, add_statistics);
}

}  // namespace

void register_phase_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool),
                               const std::string& cli, const std::string& out_dir) {
  for (const Method& method : kMethods)
    for (const Phase& phase : kPhases) {
      const Scene scene = phase_scene(phase, method);
      if (std::string(method.name) == "direct")
        register_bare(name_of("bare", method, phase), scene, add_statistics);
      register_simulate(name_of("phase", method, phase), scene, add_statistics);
      register_cli(name_of("cli", method, phase), scene, phase, method, cli, out_dir,
                   add_statistics);
    }
}

std::string phase_plot_data(const std::function<double(const std::string&)>& best) {
  std::string csv = "case,bare loop,simulate(),impact run,target,impact run target\n";
  for (const Method& method : kMethods) {
    const double target = 1.5 * best(name_of("phase", method, kPhases[0]));
    for (const Phase& phase : kPhases) {
      const double bare = best(name_of("bare", method, phase));
      csv += std::string(method.name) + " " + phase.name + "," + round_trip(bare) + "," +
             round_trip(best(name_of("phase", method, phase))) + "," +
             round_trip(best(name_of("cli", method, phase))) + "," + round_trip(target) + "," +
             round_trip(1.5 * bare) + "\n";
    }
  }
  return csv;
}

std::string processor_name() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model, family, number;
  const auto value = [&] { return line.substr(line.find(':') + 2); };
  while (std::getline(cpuinfo, line) && line.find(':') != std::string::npos) {
    if (line.rfind("model name", 0) == 0) model = value();
    if (line.rfind("cpu family", 0) == 0) family = value();
    if (line.rfind("model\t", 0) == 0) number = value();
  }
  if (model.empty()) return "unknown processor";
  return model + (family.empty() ? "" : ", family " + family + " model " + number);
}

}  // namespace impact
