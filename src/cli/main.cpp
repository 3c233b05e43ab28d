// The `impact` command: a thin layer over the library (scene -> solver -> CSV).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cli/help_format.hpp"
#include "cli/plot.hpp"
#include "cli/run_command.hpp"
#include "cli/sweep.hpp"
#include "cli/work_precision_command.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "impact/version.hpp"
#include "scene/read_scene.hpp"
#include "scene/scene_help.hpp"

namespace {

constexpr int kNumericalFailure = 1, kBadInput = 2;

// The exit code of --help or --version once their text is out: a write that failed (a full disk,
// /dev/full, a closed pipe) is an error, not success with nothing printed.
int written(int code) {
  std::cout.flush();
  if (std::cout && std::fflush(stdout) == 0) return code;
  std::fprintf(stderr, "impact: error: standard output: write failed: %s\n", std::strerror(errno));
  return kNumericalFailure;
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
  app.set_version_flag("--version", "impact " + std::string(impact::version()) + " (commit " +
                                        std::string(impact::commit()) + ")");
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
  impact::cli::RunOptions run_options;
  std::string against;
  run_cmd->add_option("SCENE", run_options.scene, "Scene file (TOML); see docs/scenes.md")
      ->required();
  run_cmd
      ->add_option("--set", run_options.overrides,
                   "Override or add a scene key, table.key=value; the value is read as TOML "
                   "(a bare word as a string), e.g. --set time.h=1e-4 --set floor.cor=0.5 "
                   "--set method.name=exact. Repeatable.")
      ->allow_extra_args(false);  // one value per --set, so `--set a=1 SCENE` still sees SCENE
  run_cmd
      ->add_option("--unset", run_options.unsets,
                   "Remove a key or a table of the scene file for this run, table.key or table "
                   "(applied before --set), e.g. --unset floor.cor. Repeatable.")
      ->allow_extra_args(false);
  run_cmd->add_option("--out,-o", run_options.out,
                      "Output CSV file (default: standard output). Written to a temporary file "
                      "and renamed when the run succeeds; a device, a pipe or /dev/stdout is "
                      "written in place.");
  run_cmd->add_option(
      "--events", run_options.events,
      "Also write the run's events as CSV to this file ('-': standard output, when --out is a "
      "file), header t,kind,v_before,v_after, one row per impact, stick (the particle comes to "
      "rest on the floor) or lift (it leaves the floor after resting); exact events where the "
      "method knows them, else read off the contact steps (docs/events.md). With [bonding] also "
      "debond (beta falls to bonding.debond_below), capture (a flight turns back to the floor) "
      "and escape (f = 0: it never comes back), and columns beta,D. Written as --out is.");
  run_cmd
      ->add_option("--against", against,
                   "Also measure the run against a reference solution and print the errors on "
                   "standard error: 'exact' (the event-driven solution) gives the sup-norm error "
                   "of u, the L1 error of v, the final energy error and the first impact time's "
                   "error, with the wall time")
      ->check(CLI::IsMember({"exact"}));
  run_cmd->add_flag("--force", run_options.force,
                    "Write the rows and the events even when there are more than --max-rows of "
                    "them (or 4 GB)");
  run_cmd
      ->add_option("--max-rows", run_options.max_rows,
                   "The most rows a run writes without --force (it refuses to start beyond), and "
                   "the most events (it stops when they pass it)")
      ->default_val(1e8)
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--no-provenance", run_options.no_provenance,
                    "Do not write OUT.json beside --out: where the rows came from (version, "
                    "commit, scene text and --set, the scene as run with its defaults, processor, "
                    "date, summary); not written for standard output, a pipe or a device");
  run_cmd->add_flag("--quiet,-q", run_options.quiet,
                    "Do not print the progress and summary lines on standard error (the errors "
                    "--against exact measures are printed still)");
  run_cmd->footer(
      impact::wrap(
          "Rows are written at t = l h for every output.every-th step l, and always for "
          "the first and the last step; numbers have 17 significant digits, so they "
          "read back exactly.\nA row stands for the steps since the previous row: u, v and E "
          "are the state at its t_l; N is the mean contact force over those steps (with "
          "output.every = 1, N^{l-1} of (4-1): the contact impulse over (t_{l-1}, t_l] "
          "divided by h), so that the row's interval times N is the contact impulse in it and "
          "no impact is lost between rows; iterations is their sum, so that the column adds "
          "up to the run's total.",
          impact::cli::kHelpWidth) +
      "\n\n" + impact::scene_help(impact::cli::kHelpWidth) + "\n" + epilogue);

  impact::cli::PlotOptions plot;
  CLI::App* plot_cmd = impact::cli::add_plot_command(app, plot);

  impact::cli::SweepOptions sweep;
  CLI::App* sweep_cmd = impact::cli::add_sweep_command(app, sweep);

  impact::cli::WorkPrecisionCommandOptions work_precision;
  CLI::App* work_precision_cmd = impact::cli::add_work_precision_command(app, work_precision);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return written(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return written(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return written(app.exit(e));
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  if (plot_cmd->parsed()) return impact::cli::plot_command(plot);
  bool in_place = true;
  try {
    if (sweep_cmd->parsed()) {
      sweep.arguments.assign(argv, argv + argc);
      return impact::cli::run_sweep(sweep);
    }
    if (work_precision_cmd->parsed()) {
      in_place = false;  // the table, its sidecar and the figure appear only when all are whole
      work_precision.arguments.assign(argv, argv + argc);
      return impact::cli::run_work_precision_command(work_precision);
    }
    run_options.against_exact = against == "exact";
    run_options.arguments.assign(argv, argv + argc);
    return impact::cli::run_command(run_options, in_place);
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
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr,
                 "impact: error: out of memory: the process may not allocate what the run needs "
                 "(ulimit -v?)%s\n",
                 in_place ? "" : " (no output file written)");
    return kNumericalFailure;
  } catch (const std::exception& e) {
    // Caught so that the stack unwinds and AtomicFile removes its temporary file (a force
    // expression that is not finite at some t comes here, naming t).
    std::fprintf(stderr, "impact: error: %s%s\n", e.what(),
                 in_place ? "" : " (no output file written)");
    return kNumericalFailure;
  }
}
