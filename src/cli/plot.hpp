// `impact plot CSV [--out FILE]`: a quick look at one run, one panel per channel of its CSV
// (u, v, N, E, iterations), in the style of the paper figures, drawn by gnuplot.
#pragma once

#include <string>

namespace impact::cli {

// The gnuplot script that draws `csv` (whose header line is `header`) into `out` (.png, .pdf or
// .svg); throws std::invalid_argument for a header without a channel or an unknown extension.
std::string plot_script(const std::string& csv, const std::string& header, const std::string& out);

// Reads the CSV's header, runs gnuplot on the script; returns the exit code (0, 1 when gnuplot
// fails, 2 for a bad CSV or output name).
int plot_command(const std::string& csv, const std::string& out);

}  // namespace impact::cli
