// The `impact` command: a thin layer over the library (scene -> solver -> CSV).
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/help_format.hpp"
#include "cli/plot.hpp"
#include "cli/sweep.hpp"
#include "impact/error_norms.hpp"
#include "impact/output.hpp"
#include "impact/registry.hpp"
#include "impact/run.hpp"
#include "scene/read_scene.hpp"
#include "scene/scene_help.hpp"

namespace {

constexpr int kOk = 0, kNumericalFailure = 1, kBadInput = 2;
// Beyond these a run asks for output.every or --force before it starts.
constexpr double kMaxRowsUnasked = 1e8, kMaxBytesUnasked = 4e9;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A progress line on standard error ("impact: 42% of 100000000 steps, 3 s, about 4 s left"),
// redrawn in place, for runs that take more than a couple of seconds. update() is meant to be
// called every kCheckEvery steps, not every step: it reads the clock.
class Progress {
 public:
  Progress(bool enabled, std::int64_t steps, Clock::time_point start)
      : enabled_(enabled), steps_(steps), start_(start) {}

  void update(std::int64_t l) {
    if (!enabled_) return;
    const double elapsed = seconds_since(start_);
    if (elapsed < kQuietSeconds || elapsed < shown_ + kRedrawSeconds) return;
    shown_ = elapsed;
    const double done = static_cast<double>(l) / static_cast<double>(steps_);
    std::fprintf(stderr, "\rimpact: %3.0f%% of %lld steps, %.0f s, about %.0f s left\x1b[K",
                 100.0 * done, static_cast<long long>(steps_), elapsed,
                 elapsed * (1.0 - done) / done);
    drawn_ = true;
  }
  // Erases the line, so that the summary line (or an error message) starts on a clean line.
  void finish() {
    if (drawn_) std::fputs("\r\x1b[K", stderr);
    drawn_ = false;
  }
  ~Progress() { finish(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Steps between two update() calls: 2^16 steps of the fastest solver (direct, ~3 ns a step) take
  // 0.2 ms, so the clock is read a few thousand times a second, not a billion.
  static constexpr std::int64_t kCheckEvery = std::int64_t{1} << 16;

 private:
  static constexpr double kQuietSeconds = 2.0;   // nothing is shown for shorter runs
  static constexpr double kRedrawSeconds = 0.5;  // at most two redraws a second
  bool enabled_;
  std::int64_t steps_;
  Clock::time_point start_;
  double shown_ = 0.0;
  bool drawn_ = false;
};

// The output would replace the scene it was computed from (e.g. --out no_cor.toml).
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// `in_place` tells main() whether rows may have gone out before a failure (to standard output, a
// pipe, a device) or nothing was written (a file that appears only when the run succeeds).
int run(const std::string& scene_path, const std::vector<std::string>& overrides,
        const std::vector<std::string>& unsets, const std::string& out_path, bool quiet,
        bool against_exact, bool force, bool& in_place) {
  using namespace impact;
  const auto start = Clock::now();
  Run loaded = load_run(scene_path, overrides, unsets);
  const Scene& scene = loaded.scene;
  // T not a multiple of h: the grid stops short of T (Grid::covering); say so, and which h fits.
  if (!quiet && scene.grid.end() < scene.T && scene.T - scene.grid.end() > 1e-12 * scene.T)
    std::fprintf(stderr,
                 "impact: note: T = %s is not a multiple of h = %s: the run ends at t = %s, the "
                 "last grid time before T; h = %s divides T\n",
                 round_trip(scene.T).c_str(), round_trip(scene.grid.h).c_str(),
                 round_trip(scene.grid.end()).c_str(),
                 round_trip(scene.T / static_cast<double>(scene.grid.steps + 1)).c_str());
  const bool to_stdout = out_path.empty() || out_path == "-";
  if (!to_stdout && same_file(out_path, scene_path))
    throw OutputError(out_path + ": --out names the scene file itself; give another file name",
                      true);
  // A run that would write more than ~1e8 rows (gigabytes) is most likely a missing output.every.
  const std::int64_t every_step = scene.output.every, steps = scene.grid.steps;
  const double rows_due = static_cast<double>(steps / every_step + 1 + (steps % every_step != 0));
  const double bytes_due = rows_due * 25.0 * static_cast<double>(scene.output.channels.size() + 1);
  if (!force && (rows_due > kMaxRowsUnasked || bytes_due > kMaxBytesUnasked))
    throw SceneError(scene_path + ": output.every = " + std::to_string(scene.output.every) +
                     ": this run would write " + round_trip(rows_due) + " rows (about " +
                     round_trip(std::round(bytes_due / 1e9)) +
                     " GB); set output.every (e.g. --set output.every=" +
                     std::to_string(static_cast<long long>(
                         std::ceil(static_cast<double>(scene.grid.steps) / 1e6))) +
                     " for 1e6 rows) or pass --force");
  AtomicFile file(out_path);
  in_place = file.in_place();
  CsvWriter csv(file.stream(), scene.model, scene.output.channels);
  csv.header();
  RowSchedule rows(scene.output.every, scene.grid.steps);
  // Progress only where someone watches it: stderr is a terminal that the CSV does not go to.
  Progress progress(!quiet && isatty(2) && !(to_stdout && isatty(1)), scene.grid.steps, start);
  // The observer's common path is one comparison, so that the step loop keeps its state in
  // registers (run.hpp): the row and the progress check run out of line, on copies of the state,
  // at the next step where one of them may be due (measured with run.hpp's loop: 10.2 -> 2.7 ns
  // per direct step on Figure 3; asking rows.due() at every step instead: 4.5 rather than 3.0 ns
  // on Figure 4 with COR; experiments/performance/README.md).
  const std::int64_t every = scene.output.every, last = scene.grid.steps;
  std::int64_t next_check = Progress::kCheckEvery, next_event = 0;
  const auto event = [&](std::int64_t l, State s, StepInfo info) __attribute__((noinline)) {
    if (rows.due(l)) csv.row(scene.grid.t(l), s, info);
    if (l == next_check) {
      next_check = l + Progress::kCheckEvery;
      file.check();  // a full disk stops the run here
      progress.update(l);
    }
    // Rows are due only at multiples of `every` and at the last step.
    next_event = std::min(every < last - l ? l + every : last, next_check);
  };
  const auto rows_and_progress = [&](std::int64_t l, const State& s, const StepInfo& info) {
    if (l == next_event) [[unlikely]]
      event(l, s, info);
  };
  std::optional<ErrorObserver> errors;
  RunSummary summary;
  if (against_exact) {  // the error against the exact solution, accumulated as the run streams
    errors.emplace(scene.model, scene.initial, scene.grid);
    summary = simulate(loaded.stepper, scene.initial, scene.grid,
                       [&](std::int64_t l, const State& s, const StepInfo& info) {
                         (*errors)(l, s, info);
                         rows_and_progress(l, s, info);
                       });
  } else {
    summary = simulate(loaded.stepper, scene.initial, scene.grid, rows_and_progress);
  }
  file.commit();
  progress.finish();
  const double seconds = seconds_since(start);
  if (!quiet) {
    const MethodInfo& method = method_info(scene.method);
    std::fprintf(stderr, "impact: %s, %lld steps, %lld contact steps", method.name.data(),
                 static_cast<long long>(summary.steps),
                 static_cast<long long>(summary.contact_steps));
    if (method.has_iterations)
      std::fprintf(stderr, ", %lld iterations (max %d per step)",
                   static_cast<long long>(summary.iterations), summary.max_iterations);
    std::fprintf(stderr, ", %.3f s wall\n", seconds);
  }
  if (errors) {
    const ErrorNorms e = errors->result(summary);
    std::fprintf(stderr,
                 "impact: against exact: sup|u - u_exact| = %s, h sum|v - v_exact| = %s, "
                 "|E(T) - E_exact(T)| = %s, first impact time error = %s, %.3f s wall\n",
                 round_trip(e.sup_u).c_str(), round_trip(e.l1_v).c_str(),
                 round_trip(e.energy_end).c_str(),
                 std::isnan(e.first_impact) ? "none (no impact in one of the two)"
                                            : round_trip(e.first_impact).c_str(),
                 seconds);
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, reported like a full disk,
  // instead of the default action of SIGXFSZ, which kills the process and leaves the temporary.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{
      "impact: a particle falls onto a rigid floor, u'' = N + f, 0 <= u - phi ⟂ N >= 0.\n"
      "Reproduces Ahn and Wolf, Dynamic impact of a particle, Involve 6:2 (2013).",
      "impact"};
  app.formatter(std::make_shared<impact::cli::WrappingFormatter>());  // before the subcommands
  app.set_version_flag("--version", "impact 0.1.0");
  const std::string epilogue =  // the exit codes and an example
      "Exit codes: 0 ok, 1 numerical failure or write error, 2 bad input.\n"
      "Example: impact run experiments/figure3/no_cor.toml --set time.h=1e-4 -o u.csv";
  app.footer(
      "'impact run --help' lists the run options, every scene key with its default and\n"
      "range, the methods and the channels.\n" +
      epilogue);
  app.require_subcommand(1);

  CLI::App* run_cmd = app.add_subcommand(
      "run", "Run one scene and write its trajectory as CSV (header t,<channels>).");
  std::string scene_path, out_path;
  std::vector<std::string> overrides, unsets;
  bool quiet = false;
  std::string against;
  run_cmd->add_option("SCENE", scene_path, "Scene file (TOML); see README.md, 'Scenes'")
      ->required();
  run_cmd
      ->add_option("--set", overrides,
                   "Override or add a scene key, table.key=value; the value is read as TOML "
                   "(a bare word as a string), e.g. --set time.h=1e-4 --set floor.cor=0.5 "
                   "--set method.name=exact. Repeatable.")
      ->allow_extra_args(false);  // one value per --set, so `--set a=1 SCENE` still sees SCENE
  run_cmd
      ->add_option("--unset", unsets,
                   "Remove a key or a table of the scene file for this run, table.key or table "
                   "(applied before --set), e.g. --unset floor.cor. Repeatable.")
      ->allow_extra_args(false);
  run_cmd->add_option("--out,-o", out_path,
                      "Output CSV file (default: standard output). Written to a temporary file "
                      "and renamed when the run succeeds; a device, a pipe or /dev/stdout is "
                      "written in place.");
  run_cmd
      ->add_option("--against", against,
                   "Also measure the run against a reference solution and print the errors on "
                   "standard error: 'exact' (the event-driven solution) gives the sup-norm error "
                   "of u, the L1 error of v, the final energy error and the first impact time's "
                   "error, with the wall time")
      ->check(CLI::IsMember({"exact"}));
  bool force = false;
  run_cmd->add_flag("--force", force,
                    "Write the rows even when there are more than 1e8 of them (or 4 GB)");
  run_cmd->add_flag("--quiet,-q", quiet,
                    "Do not print the progress and summary lines on standard error");
  run_cmd->footer(
      impact::wrap(
          "Rows are written at t = l h for every output.every-th step l, and always for "
          "the first and the last step; numbers have 17 significant digits, so they "
          "read back exactly.\nN in the row at t_l is N^{l-1} of (4-1): the contact impulse "
          "over (t_{l-1}, t_l] divided by h.",
          impact::cli::kHelpWidth) +
      "\n\n" + impact::scene_help(impact::cli::kHelpWidth) + "\n" + epilogue);

  CLI::App* plot_cmd = app.add_subcommand(
      "plot",
      "Draw the CSV of a run (impact run ... -o run.csv) with gnuplot: one panel per channel.");
  std::string plot_csv, plot_out;
  plot_cmd->add_option("CSV", plot_csv, "A CSV written by impact run")->required();
  plot_cmd->add_option("--out,-o", plot_out,
                       "The figure: .png, .pdf or .svg (default: the CSV's name with .png)");

  impact::cli::SweepOptions sweep;
  CLI::App* sweep_cmd = impact::cli::add_sweep_command(app, sweep);

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

  if (plot_cmd->parsed()) {
    if (plot_out.empty())
      plot_out =
          plot_csv.substr(0, plot_csv.rfind(".csv") == std::string::npos ? plot_csv.size()
                                                                         : plot_csv.rfind(".csv")) +
          ".png";
    return impact::cli::plot_command(plot_csv, plot_out);
  }
  bool in_place = true;
  try {
    if (sweep_cmd->parsed()) return impact::cli::run_sweep(sweep);
    return run(scene_path, overrides, unsets, out_path, quiet, against == "exact", force, in_place);
  } catch (const impact::SceneError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return kBadInput;
  } catch (const impact::OutputError& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return e.bad_path ? kBadInput : kNumericalFailure;
  } catch (const impact::NumericalError& e) {
    std::fprintf(stderr, "impact: numerical failure: %s%s\n", e.what(),
                 in_place ? "" : " (no output file written)");
    return kNumericalFailure;
  } catch (const std::exception& e) {
    // Caught so that the stack unwinds and AtomicFile removes its temporary file.
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return kNumericalFailure;
  }
}
