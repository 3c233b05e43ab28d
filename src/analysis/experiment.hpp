// What every experiment shares: where its scenes are and where its data go (ExperimentContext),
// and the `main` of its driver (experiment_main). An experiment is one function,
// toml::table run(const ExperimentContext&), that returns its key numbers and writes its data
// files; the driver and the test call that same function.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

namespace impact {

struct ExperimentContext {
  std::string source_dir;   // the repository: scenes are under experiments/<name>/
  std::string results_dir;  // where data files go; empty: none is written (the tests)

  // source_dir/experiments/<experiment>/<file>
  std::string scene_path(std::string_view experiment, std::string_view file) const;
  bool writes() const { return !results_dir.empty(); }
  // Writes results_dir/<file> whole or not at all; nothing when writes() is false. `make` is
  // called only when the file is written, so a test does not build text it throws away.
  template <class Make>
  void write(std::string_view file, Make&& make) const {
    if (writes()) write_text(file, make());
  }
  void write_text(std::string_view file, const std::string& text) const;
};

struct Experiment {
  std::string_view name;         // experiments/<name>, exp_<name>
  std::string_view description;  // one line, for --help and the summary's header
  toml::table (*run)(const ExperimentContext&);
};

// The driver's main: `exp_<name> [--source DIR] RESULTS_DIR` runs the experiment with the scenes
// of DIR (default: the source tree it was built from), writes RESULTS_DIR/summary.toml and its
// data files, and exits 0; 2 for a bad command line, 1 for a failure. --help explains.
int experiment_main(int argc, char** argv, const Experiment& experiment,
                    std::string_view default_source_dir);

// The summary file: a header naming the experiment, then the table.
std::string summary_text(const Experiment& experiment, const toml::table& summary);

// One array of numbers for a summary.
toml::array toml_array(const std::vector<double>& values);

}  // namespace impact
