// `impact run SCENE`: the scene's trajectory as CSV rows, and with --events its impacts, sticks and
// lifts as CSV rows of their own, each file written whole or not at all (csv.hpp), with the
// provenance of the rows in a sidecar OUT.json (provenance.hpp) when they go to a file.
#pragma once

#include <string>
#include <vector>

namespace impact::cli {

struct RunOptions {
  std::vector<std::string> arguments;  // the command line, for the provenance sidecar
  std::string scene;
  std::vector<std::string> overrides, unsets;
  std::string out;     // empty or "-": standard output
  std::string events;  // empty: no events; "-": standard output
  bool quiet = false;
  bool against_exact = false;
  bool force = false;          // no limit on the rows and events written
  double max_rows = 1e8;       // without force: the most rows, and the most events, a run writes
  bool no_provenance = false;  // no OUT.json beside the rows
};

// Runs the scene and returns the exit code (0). Throws SceneError (bad input), OutputError,
// NumericalError, or std::runtime_error from a force expression that is not finite at some t.
// `in_place` tells the caller whether rows may have gone out before a failure (to standard output,
// a pipe, a device) or nothing was written (files that appear only when the run succeeds).
int run_command(const RunOptions& options, bool& in_place);

}  // namespace impact::cli
