// The `impact` command: a thin layer over the library (scene -> solver -> CSV).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "impact/scene.hpp"

namespace {

constexpr int kOk = 0, kNumericalFailure = 1, kBadInput = 2;

std::string methods_help() {
  std::string text = "Methods ([method] name = ...):\n";
  for (const auto& m : impact::methods())
    text += "  " + std::string(m.name) + std::string(12 - m.name.size(), ' ') +
            std::string(m.summary) + "\n";
  return text;
}

int run(const std::string& scene_path, const std::vector<std::string>& overrides,
        const std::string& out_path, bool quiet) {
  using namespace impact;
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  AnyStepper stepper = [&] {
    scene = load_scene(scene_path, overrides);
    return make_stepper(scene);
  }();
  AtomicFile file(out_path);
  CsvWriter csv(file.stream(), scene.model, scene.output.channels);
  csv.header();
  const std::int64_t every = scene.output.every, last = scene.grid.steps;
  std::int64_t next_row = 0;  // a countdown instead of l % every: no division in the step loop
  RunSummary summary = simulate(stepper, scene.initial, scene.grid,
                                [&](std::int64_t l, const State& s, const StepInfo& info) {
                                  if (l == next_row || l == last) {
                                    csv.row(scene.grid.t(l), s, info);
                                    next_row = l + every;
                                  }
                                });
  file.commit();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!quiet) {
    std::fprintf(stderr, "impact: %s, %lld steps, %lld contact steps", scene.method.c_str(),
                 static_cast<long long>(summary.steps),
                 static_cast<long long>(summary.contact_steps));
    if (find_method(scene.method)->has_iterations)
      std::fprintf(stderr, ", %lld iterations (max %d per step)",
                   static_cast<long long>(summary.iterations), summary.max_iterations);
    std::fprintf(stderr, ", %.3f s wall\n", seconds);
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "impact: a particle falling onto a rigid floor, u'' = N + f, 0 <= u - phi ⟂ N >= 0.\n"
      "Reproduces J. Ahn and J. R. Wolf, Dynamic impact of a particle, Involve 6:2 (2013).",
      "impact"};
  app.set_version_flag("--version", "impact 0.1.0");
  app.footer(methods_help() +
             "\nExit codes: 0 ok, 1 numerical failure or write error, 2 bad input.\n"
             "Run options: --set table.key=value (repeatable), --out/-o FILE, --quiet/-q;\n"
             "see 'impact run --help'.\n"
             "Example: impact run experiments/figure3/no_cor.toml --set time.h=1e-4 --out u.csv");
  app.require_subcommand(1);

  CLI::App* run_cmd = app.add_subcommand(
      "run", "Run one scene and write its trajectory as CSV (header t,<channels>).");
  std::string scene_path, out_path;
  std::vector<std::string> overrides;
  bool quiet = false;
  run_cmd->add_option("SCENE", scene_path, "Scene file (TOML); see README.md, 'Scenes'")
      ->required();
  run_cmd
      ->add_option("--set", overrides,
                   "Override or add a scene key, table.key=value; the value is read as TOML "
                   "(a bare word as a string), e.g. --set time.h=1e-4 --set floor.cor=0.5 "
                   "--set method.name=exact. Repeatable.")
      ->allow_extra_args(false);  // one value per --set, so `--set a=1 SCENE` still sees SCENE
  run_cmd->add_option("--out,-o", out_path,
                      "Output CSV file (default: standard output). Written to a temporary file "
                      "and renamed when the run succeeds.");
  run_cmd->add_flag("--quiet,-q", quiet, "Do not print the summary line on standard error");
  run_cmd->footer(
      "Rows are written at t = l h for every output.every-th step l, and always at t = 0 and\n"
      "at the last step; numbers have 17 significant digits so that they read back exactly.\n"
      "N in the row at t_l is N^{l-1} of (4-1): the contact impulse over (t_{l-1}, t_l] / h.\n\n" +
      methods_help() + "\nExit codes: 0 ok, 1 numerical failure or write error, 2 bad input.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  try {
    return run(scene_path, overrides, out_path, quiet);
  } catch (const impact::SceneError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return kBadInput;
  } catch (const impact::OutputError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return e.bad_path ? kBadInput : kNumericalFailure;
  } catch (const impact::NumericalError& e) {
    std::fprintf(stderr, "impact: numerical failure: %s%s\n", e.what(),
                 out_path.empty() || out_path == "-" ? "" : " (no output file written)");
    return kNumericalFailure;
  } catch (const std::exception& e) {
    // Caught so that the stack unwinds and AtomicFile removes its temporary file.
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return kNumericalFailure;
  }
}
