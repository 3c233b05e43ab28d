// `impact work-precision SCENE`: every chosen time-stepper's errors against the scene's reference
// and the CPU time of its solve over a sweep of h, the observed orders, and a log-log figure: the
// recipe of experiments/work_precision (work_precision_curves.hpp's step_curves) for any scene
// (docs/outputs.md, "Work against precision for your own scene").
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "analysis/work_precision_curves.hpp"
#include "cli/plot_figure.hpp"

namespace impact::cli {

// The methods swept when --methods is not given, less those that cannot run the scene.
constexpr const char* kDefaultMethods = "direct,moreau_jean,fb_newton";

struct WorkPrecisionCommandOptions {
  std::vector<std::string> arguments;  // the command line, for the provenance sidecar
  std::string scene;
  std::vector<std::string> sets;
  std::string methods;  // empty: those of kDefaultMethods that can run the scene
  std::string steps;    // --h SPEC; empty: the experiment's 0.1 .. 1e-5
  std::string against;  // empty: the scene's reference
  int repeat = 5;
  double max_steps = 1e9;  // the most grid steps one run may take without --force
  bool force = false;
  std::string out, plot;
  bool quiet = false;
  bool no_provenance = false;
};

// Adds the `work-precision` subcommand, whose options fill `options`.
CLI::App* add_work_precision_command(CLI::App& app, WorkPrecisionCommandOptions& options);

// Measures, writes the table (and its sidecar, and the figure) and returns the exit code 0. Bad
// input throws SceneError (exit code 2), output errors OutputError, as for `impact run`.
int run_work_precision_command(const WorkPrecisionCommandOptions& options);

// The figure: every error measure against CPU time (first row) and against h (second row), one
// curve per method, log-log (work_precision_figure.cpp). ARG1 is the scene's file name.
Figure work_precision_figure(const std::vector<impact::Curve>& curves, const std::string& reference,
                             int repeat);

}  // namespace impact::cli
