// `impact sweep`: one scene over a grid of parameters, on every core, in shards for many machines,
// and `impact sweep --merge` to join the shards' parts (docs/sweeps.md).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace impact::cli {

struct SweepOptions {
  std::vector<std::string> arguments;  // the command line, for the provenance sidecar
  std::string scene;
  std::vector<std::string> sets, varies;
  std::string summary, against, shard;
  std::string instruction_set;  // the ensemble's vector code; empty: the widest there is
  int threads = 0;              // 0: one per core
  std::vector<std::string> merge;
  std::string out;
  bool quiet = false;
  bool no_provenance = false;  // no OUT.json beside the rows
};

// Adds the `sweep` subcommand, whose options fill `options`.
CLI::App* add_sweep_command(CLI::App& app, SweepOptions& options);

// Runs a sweep or a merge; returns the exit code: 0, or 1 when a point failed numerically. Bad
// input throws SceneError (exit code 2), output errors OutputError, as for `impact run`.
int run_sweep(const SweepOptions& options);

// `impact sweep --merge PART... --out FILE` (sweep_merge.cpp).
int merge_parts(const std::vector<std::string>& parts, const std::string& out);

}  // namespace impact::cli
