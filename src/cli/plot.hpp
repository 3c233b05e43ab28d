// `impact plot CSV [--out FILE] [--against REF.csv] [--events EVENTS.csv]`: a quick look at a run
// (one panel per channel), at its events, or at a sweep (one panel per quantity against the varied
// key), drawn by gnuplot.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "impact/output/atomic_file.hpp"

namespace impact::cli {

struct PlotOptions {
  std::string csv, out, against, events;
};

// gnuplot could not start, failed, or drew nothing (exit code 1).
class GnuplotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `gnuplot -c /dev/stdin NAME...` with the script on its standard input and its standard
// output, where the script draws, on `out`. The names become ARG1, ARG2, ...: never commands.
// Throws GnuplotError.
void run_gnuplot(const std::string& script, const std::vector<std::string>& names, AtomicFile& out);

// Adds the `plot` subcommand, whose options fill `options`.
CLI::App* add_plot_command(CLI::App& app, PlotOptions& options);

// Reads the CSVs, draws the figure with gnuplot into a temporary file and renames it over --out
// when gnuplot succeeded; returns the exit code: 0, 1 when gnuplot cannot start or fails or the
// figure cannot be written, 2 for a bad CSV or output name.
int plot_command(const PlotOptions& options);

}  // namespace impact::cli
