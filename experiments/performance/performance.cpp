// Throughput of the solvers, with Google Benchmark. CPU time of the solve alone, output
// off, after a warm-up, repeated; the minimum and the median over the repetitions are reported.
//   stepper/<method>/<scene>   ns per step through simulate() (as `impact run` calls it), for
//                              direct, moreau_jean, fb_newton, penalty (per grid step and per ODE
//                              step) and exact (the closed-form reference sampled on the grid)
//   exact_impacts              ns per impact of the exact solution (impact time and speed)
//   impacts/..., stepper/.../table_period1, ...   the time-dependent force (performance_forced.hpp)
//   ensemble/<method>/<isa>    particle-steps per second of the vectorised ensemble
//   cli/<method>/<scene>/<n>   `impact run` as a user runs it: a process, a scene file, n steps,
//                              CSV output decimated to about 10^4 rows; CPU time of the child
//   cli_rows                   `impact run` writing every step: the cost of one CSV row
// Usage: exp_performance RESULTS_DIR IMPACT_CLI [Google Benchmark flags]
// Writes RESULTS_DIR/benchmarks.csv, RESULTS_DIR/summary.toml and RESULTS_DIR/table.md.
#include <benchmark/benchmark.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/markdown.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "performance_cli.hpp"
#include "performance_forced.hpp"
#include "performance_phases.hpp"
#include "performance_ratios.hpp"
#include "scene/read_scene.hpp"

namespace {

using namespace impact;

constexpr int kRepetitions = 5;

const impact::Experiment kPerformance{
    "performance", "Throughput of the solvers, the ensemble and impact run (Google Benchmark)",
    nullptr};
const impact::ExperimentContext kSource{IMPACT_SOURCE_DIR, ""};

// experiments/<scene>.toml
std::string scene_path(const std::string& scene) {
  const auto slash = scene.find('/');
  return kSource.scene_path(scene.substr(0, slash), scene.substr(slash + 1) + ".toml");
}

// The paper's scenes (Section 5): "figure3/no_cor" is f = 0 with one impact (almost every step
// is free flight); "figure4/no_cor" is gravity without COR (direct ends in its period-2 chatter on
// the floor, so about half its steps are contact steps); "figure4/cor075" bounces to rest at the
// Zeno time t ~ 7.0 and rests on the floor (a contact step each step) until T = 10.
const std::vector<std::string> kScenes = {"figure3/no_cor", "figure4/no_cor", "figure4/cor075"};

std::string label(const std::string& scene) {
  std::string s = scene;
  std::replace(s.begin(), s.end(), '/', '_');
  return s;
}

// Repeated; min and median over the repetitions. A timed benchmark first warms up for 0.05 s and
// then runs for at least 0.2 s per repetition; a process benchmark (one run per repetition) warms
// up by one untimed run.
void add_statistics(benchmark::internal::Benchmark* b, bool process = false) {
  b->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true)
      ->ComputeStatistics(
          "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
      ->ComputeStatistics(
          "max", [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); })
      ->Unit(benchmark::kMillisecond);
  if (process)
    b->UseManualTime()->Iterations(1);
  else
    b->MinWarmUpTime(0.05)->MinTime(0.2);
}

// One full run of the scene with these method parameters and step per iteration, output off (the
// observer does nothing).
void register_stepper(const MethodParams& method, const std::string& scene, double h,
                      const std::string& tag = "") {
  Scene s = load_scene(scene_path(scene));
  s.method = method;
  s.grid = Grid::covering(s.T, h);
  const std::string name = "stepper/" + std::string(method_name(method)) +
                           (tag.empty() ? "" : "_" + tag) + "/" + label(scene);
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [s](benchmark::State& state) {
    RunSummary summary;
    for (auto _ : state) {
      AnyStepper stepper = make_stepper(s);
      summary =
          simulate(stepper, s.initial, s.grid, [](std::int64_t, const State&, const StepInfo&) {});
      benchmark::DoNotOptimize(summary);
    }
    const auto per_step =
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert;
    state.counters["s_per_step"] = benchmark::Counter(static_cast<double>(s.grid.steps), per_step);
    if (summary.iterations > 0)
      state.counters["s_per_iteration"] =
          benchmark::Counter(static_cast<double>(summary.iterations), per_step);
    state.counters["contact_fraction"] =
        static_cast<double>(summary.contact_steps) / static_cast<double>(s.grid.steps);
  });
  add_statistics(b);
}

// The exact solution's own cost per impact: the time and the speed of impact k, k = 1..K, for the
// elastic bounce under gravity (every flight as long as the first, so K impacts in K flights).
void register_exact_impacts() {
  auto* b = benchmark::RegisterBenchmark("exact_impacts", [](benchmark::State& state) {
    const Model model{0.0, -9.80665, std::nullopt};
    const ExactSolution exact(model, State{5.0, -1.0});
    constexpr std::int64_t kImpacts = 100000;
    for (auto _ : state) {
      double sum = 0;
      for (std::int64_t k = 1; k <= kImpacts; ++k)
        sum += *exact.impact_time(k) + *exact.impact_speed(k);
      benchmark::DoNotOptimize(sum);
    }
    state.counters["s_per_impact"] = benchmark::Counter(
        kImpacts, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  });
  add_statistics(b);
}

// A parameter sweep on the paper's Figure 4 setting: drop heights 1..10 m, v0 = -1 m/s, gravity,
// every other particle with COR 0.75; each iteration steps a fresh ensemble over T = 10 s
// (10^4 steps of 1e-3 s). `settled`: the same particles after 300 s instead, all at rest, where
// those with a COR sit on a subnormal fixed point of v -> -0.75 v (v = +-2^-1073, 1.5 v rounds back
// to 2^-1073 in magnitude): every multiply by it takes the processor's slow subnormal path.
void register_ensemble(EnsembleMethod method, const std::string& method_name,
                       const std::string& isa, bool settled) {
  constexpr int kParticles = 960;
  constexpr std::int64_t kSteps = 10000, kSettle = 300000;
  const std::string name =
      std::string(settled ? "ensemble_settled/" : "ensemble/") + method_name + "/" + isa;
  auto* b = benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    std::vector<Model> models(kParticles);
    std::vector<State> initial(kParticles);
    for (int i = 0; i < kParticles; ++i) {
      models[i].f = -9.80665;
      if (i % 2) models[i].cor = 0.75;
      initial[i] = {1.0 + 9.0 * i / kParticles, -1.0};
    }
    const auto fresh = [&] {
      Ensemble e(method, models, initial, 1e-3);
      e.use(isa);
      if (settled) e.advance(kSettle);
      return e;
    };
    Ensemble ensemble = fresh();
    for (auto _ : state) {
      if (!settled) {
        state.PauseTiming();
        ensemble = fresh();
        state.ResumeTiming();
      }
      ensemble.advance(kSteps);
      benchmark::DoNotOptimize(ensemble.u().data());
    }
    state.counters["particle_steps_per_s"] = benchmark::Counter(
        static_cast<double>(kParticles * kSteps), benchmark::Counter::kIsIterationInvariantRate);
  });
  add_statistics(b);
}

void register_cli(const std::string& cli, const std::string& out_dir, const std::string& method,
                  const std::string& scene, std::int64_t steps, std::int64_t every,
                  const std::string& name) {
  const double T = load_scene(scene_path(scene)).T;
  register_cli_run(
      name,
      {cli, "run", scene_path(scene), "--set", "method.name=" + method, "--set",
       "time.h=" + round_trip(T / static_cast<double>(steps)), "--set",
       "output.every=" + std::to_string(every), "--quiet", "--out", out_dir + "/cli.csv"},
      steps, &add_statistics);
}

// Collects the min and median of every benchmark while the console shows them.
class Collector : public benchmark::ConsoleReporter {
 public:
  struct Result {
    // "time_ms" (per iteration) and the counters, over the repetitions.
    std::map<std::string, double> min, median, max;
  };
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Aggregate) continue;
      std::map<std::string, double>* into = nullptr;
      if (run.aggregate_name == "min") into = &results_[run.run_name.function_name].min;
      if (run.aggregate_name == "median") into = &results_[run.run_name.function_name].median;
      if (run.aggregate_name == "max") into = &results_[run.run_name.function_name].max;
      if (!into) continue;
      (*into)["time_ms"] = run.GetAdjustedCPUTime();
      if (run.run_name.function_name.rfind("cli", 0) == 0)
        (*into)["time_ms"] = run.GetAdjustedRealTime();
      for (const auto& [key, counter] : run.counters) (*into)[key] = counter.value;
    }
  }
  const std::map<std::string, Result>& results() const { return results_; }

 private:
  std::map<std::string, Result> results_;
};

// The quantity each benchmark is judged by, in the unit of the table.
struct Quantity {
  std::string key, unit;
  double scale;
};

Quantity quantity_of(const std::string& name) {
  if (name.rfind("ensemble", 0) == 0 || name.rfind("sweep_kernel", 0) == 0)
    return {"particle_steps_per_s", "particle-steps/s", 1.0};
  if (name.rfind("cli_sweep", 0) == 0)  // cli_sweep and cli_sweep_final
    return {"s_per_step", "ns/particle-step", 1e9};
  if (name == "exact_impacts" || name.rfind("impacts/", 0) == 0)
    return {"s_per_impact", "ns/impact", 1e9};
  if (name == "cli_rows") return {"s_per_step", "ns/row", 1e9};
  return {"s_per_step", "ns/step", 1e9};
}

// The best and median of each benchmark: benchmarks.csv, table.md and summary.toml.
void write_tables(const std::string& dir, const Collector& collector,
                  const std::function<double(const std::string&)>& best) {
  std::string csv = "benchmark,quantity,unit,best,median\n";
  std::string md = "| benchmark | unit | best | median |\n| --- | --- | ---: | ---: |\n";
  toml::table summary{{"processor", processor_name()}};
  md = "Processor: " + processor_name() + "\n\n" + md;
  for (const auto& [name, r] : collector.results()) {
    const Quantity q = quantity_of(name);
    const auto value = [&](const std::map<std::string, double>& m, const std::string& key) {
      const auto it = m.find(key);
      return it == m.end() ? std::nan("") : it->second * (key == q.key ? q.scale : 1.0);
    };
    // The best repetition: the largest rate, the smallest time.
    const bool rate = q.key == "particle_steps_per_s";
    const double best = rate ? value(r.max, q.key) : value(r.min, q.key);
    const double median = value(r.median, q.key);
    csv += name + "," + q.key + "," + q.unit + "," + round_trip(best) + "," + round_trip(median) +
           "\n";
    md += "| `" + name + "` | " + q.unit + " | " + short_number(best) + " | " +
          short_number(median) + " |\n";
    toml::table entry{{"unit", q.unit}, {"best", best}, {"median", median}};
    if (r.median.count("s_per_iteration"))
      entry.insert("ns_per_ode_step_median", r.median.at("s_per_iteration") * 1e9);
    if (r.median.count("contact_fraction"))
      entry.insert("contact_fraction", r.median.at("contact_fraction"));
    summary.insert(name, entry);
  }
  write_text_file(dir + "/benchmarks.csv", csv);
  md += "\nThe ratios, best against best:\n\n" + ratio_table(best);
  write_text_file(dir + "/table.md", md);
  write_text_file(dir + "/summary.toml", summary_text(kPerformance, summary));
}

// For plot.gp: ns per step of each phase (performance_phases.hpp) and the ensemble's throughput
// against its targets, 1.5e9 (AVX-512) and 1e9 (AVX2) particle-steps/s for direct.
void write_plot_data(const std::string& dir, const Collector& collector) {
  const auto& results = collector.results();
  write_text_file(dir + "/plot_phases.csv", phase_plot_data([&](const std::string& name) {
                    const auto it = results.find(name);
                    if (it == results.end()) return std::nan("");
                    const auto key = it->second.min.find("s_per_step");
                    return key == it->second.min.end() ? std::nan("") : key->second * 1e9;
                  }));
  std::string ensemble = "case,T = 10 s sweep,settled at rest,target\n";
  for (const auto& [name, r] : results)
    if (name.rfind("ensemble/", 0) == 0) {
      const auto settled = results.find("ensemble_settled/" + name.substr(9));
      const double target = name == "ensemble/direct/avx512f" ? 1.5e9
                            : name == "ensemble/direct/avx2"  ? 1e9
                                                              : std::nan("");
      ensemble +=
          name.substr(9) + "," + round_trip(r.max.at("particle_steps_per_s")) + "," +
          round_trip(settled == results.end() ? std::nan("")
                                              : settled->second.max.at("particle_steps_per_s")) +
          "," + round_trip(target) + "\n";
    }
  write_text_file(dir + "/plot_ensemble.csv", ensemble);
  write_text_file(dir + "/processor.txt", processor_name() + "\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s RESULTS_DIR IMPACT_CLI [Google Benchmark flags]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1], cli = argv[2];
  std::filesystem::create_directories(dir);
  argv[2] = argv[0];
  int bench_argc = argc - 2;
  char** bench_argv = argv + 2;
  benchmark::Initialize(&bench_argc, bench_argv);
  if (benchmark::ReportUnrecognizedArguments(bench_argc, bench_argv)) return 2;

  // Steps of 1e-6 s: 1e7 steps over T = 10 s, enough that the loop, not the setup, is timed.
  for (const auto& scene : kScenes) {
    for (const char* method : {"direct", "moreau_jean", "exact"})
      register_stepper(find_method(method)->defaults, scene, 1e-6);
    register_stepper(find_method("fb_newton")->defaults, scene, 1e-5);
  }
  // Normal compliance (f = 0 scene only: it takes no COR) with an explicit and an implicit GSL
  // stepper; its cost is per ODE step, the grid h only sets where it reports.
  for (const char* stepper : {"rk8pd", "msbdf"})
    register_stepper(PenaltyParams{1e6, stepper, 1e-8, 1e-10}, "figure3/no_cor", 1e-3, stepper);
  register_exact_impacts();
  register_forced_benchmarks(&add_statistics);
  for (const auto isa : Ensemble::supported_instruction_sets()) {
    for (const bool settled : {false, true}) {
      register_ensemble(EnsembleMethod::direct, "direct", std::string(isa), settled);
      register_ensemble(EnsembleMethod::moreau_jean, "moreau_jean", std::string(isa), settled);
    }
  }
  // `impact run` with decimated output: 1e7 and 1e8 steps (1e6 for fb_newton), ~1e4 rows each.
  for (const auto& scene : kScenes) {
    for (const char* method : {"direct", "moreau_jean"})
      for (std::int64_t steps : {10'000'000LL, 100'000'000LL})
        register_cli(
            cli, dir, method, scene, steps, steps / 10000,
            "cli/" + std::string(method) + "/" + label(scene) + "/" + std::to_string(steps));
    register_cli(cli, dir, "fb_newton", scene, 10'000'000, 1000,
                 "cli/fb_newton/" + label(scene) + "/10000000");
  }
  register_cli(cli, dir, "direct", "figure3/no_cor", 1'000'000, 1, "cli_rows");
  register_phase_benchmarks(&add_statistics, cli, dir);
  register_sweep_benchmarks(&add_statistics, cli, dir);

  Collector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();
  // A benchmark's best: the smallest time per step, the largest rate.
  const auto best = [&](const std::string& name) {
    const auto it = collector.results().find(name);
    if (it == collector.results().end()) return std::nan("");
    const Quantity q = quantity_of(name);
    const auto& values = q.key == "particle_steps_per_s" ? it->second.max : it->second.min;
    const auto key = values.find(q.key);
    return key == values.end() ? std::nan("") : key->second * q.scale;
  };
  write_tables(dir, collector, best);
  write_plot_data(dir, collector);
  return 0;
}
