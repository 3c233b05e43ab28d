#include "performance_ratios.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/experiment.hpp"
#include "analysis/markdown.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/output/csv.hpp"
#include "performance_cli.hpp"

namespace impact {
namespace {

const ExperimentContext kSource{IMPACT_SOURCE_DIR, ""};

constexpr int kPoints = 960;
constexpr double kH = 1e-4, kT = 100.0;
constexpr std::int64_t kSteps = 1'000'000;
constexpr double kParticleSteps = static_cast<double>(kPoints) * static_cast<double>(kSteps);

struct SweepMethod {
  const char* name;
  EnsembleMethod method;
};
constexpr SweepMethod kSweepMethods[] = {{"direct", EnsembleMethod::direct},
                                         {"moreau_jean", EnsembleMethod::moreau_jean}};

// The points of `--vary initial.u0=1:10:960` on figure4/cor075 (its f, COR and v0).
void sweep_points(std::vector<Model>& models, std::vector<State>& initial) {
  models.assign(kPoints, Model{});
  initial.assign(kPoints, State{});
  for (int i = 0; i < kPoints; ++i) {
    models[i].f = -9.80665;
    models[i].cor = 0.75;
    initial[i] = {1.0 + 9.0 * i / (kPoints - 1), -1.0};
  }
}

std::string widest_instruction_set() {
  const auto sets = Ensemble::supported_instruction_sets();
  return sets.empty() ? std::string("baseline") : std::string(sets.front());
}

}  // namespace

void register_sweep_benchmarks(void (*add_statistics)(benchmark::internal::Benchmark*, bool),
                               const std::string& cli, const std::string& out_dir) {
  const std::string isa = widest_instruction_set();
  for (const SweepMethod& m : kSweepMethods) {
    const std::string kernel = "sweep_kernel/" + std::string(m.name) + "/" + isa;
    auto* b = benchmark::RegisterBenchmark(kernel.c_str(), [=](benchmark::State& state) {
      std::vector<Model> models;
      std::vector<State> initial;
      sweep_points(models, initial);
      for (auto _ : state) {
        state.PauseTiming();
        Ensemble ensemble(m.method, models, initial, kH);
        ensemble.use(isa);
        state.ResumeTiming();
        ensemble.advance(kSteps);
        benchmark::DoNotOptimize(ensemble.u().data());
      }
      state.counters["particle_steps_per_s"] =
          benchmark::Counter(kParticleSteps, benchmark::Counter::kIsIterationInvariantRate);
    });
    add_statistics(b, false);
    for (const int threads : {1, 2})
      for (const bool final_state : {false, true}) {
        std::vector<std::string> args{cli,
                                      "sweep",
                                      kSource.scene_path("figure4", "cor075.toml"),
                                      "--vary",
                                      "initial.u0=1:10:" + std::to_string(kPoints),
                                      "--set",
                                      "method.name=" + std::string(m.name),
                                      "--set",
                                      "time.h=" + round_trip(kH),
                                      "--set",
                                      "time.T=" + round_trip(kT),
                                      "--threads",
                                      std::to_string(threads),
                                      "--quiet",
                                      "--out",
                                      out_dir + "/cli_sweep.csv"};
        if (final_state) args.insert(args.end(), {"--summary", "u_T,v_T,E_T"});
        register_cli_run(std::string(final_state ? "cli_sweep_final/" : "cli_sweep/") + m.name +
                             "/" + std::to_string(threads),
                         args, static_cast<std::int64_t>(kParticleSteps), add_statistics);
      }
  }
}

std::string ratio_table(const std::function<double(const std::string&)>& best) {
  std::string md = "| ratio | measured | target |\n| --- | ---: | ---: |\n";
  const auto row = [&](const std::string& what, double ratio, double target) {
    md += "| " + what + " | " + (std::isfinite(ratio) ? short_number(ratio) : "not run") + " | " +
          short_number(target) + " |\n";
  };
  for (const char* method : {"direct", "moreau_jean"})
    for (const char* phase : {"free_flight", "bouncing"}) {
      const std::string tail = std::string(method) + "/" + phase;
      row("`impact run` / `simulate()`, " + std::string(method) + ", " + phase,
          best("cli/" + tail) / best("phase/" + tail), 1.3);
    }
  row("direct, harmonic / constant force (figure3 no_cor, h = 1e-6)",
      best("stepper/direct/figure3_no_cor_harmonic") / best("stepper/direct/figure3_no_cor"), 1.5);
  const std::string isa = widest_instruction_set();
  for (const SweepMethod& m : kSweepMethods)
    for (const int threads : {1, 2}) {
      // ns per particle-step of CPU time over the kernel's, 1e9 / rate.
      const double kernel_ns = 1e9 / best("sweep_kernel/" + std::string(m.name) + "/" + isa);
      const std::string tail = std::string(m.name) + "/" + std::to_string(threads);
      const std::string what = "ensemble kernel (" + isa + "), " + m.name + ", " +
                               std::to_string(threads) + (threads == 1 ? " thread" : " threads");
      row("`impact sweep` / " + what, best("cli_sweep/" + tail) / kernel_ns, 1.2);
      row("`impact sweep --summary u_T,v_T,E_T` / " + what,
          best("cli_sweep_final/" + tail) / kernel_ns, 1.2);
    }
  return md;
}

}  // namespace impact
