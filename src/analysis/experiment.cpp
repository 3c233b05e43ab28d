#include "analysis/experiment.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <exception>
#include <sstream>

#include "impact/output/csv.hpp"

namespace impact {

std::string ExperimentContext::scene_path(std::string_view experiment,
                                          std::string_view file) const {
  return source_dir + "/experiments/" + std::string(experiment) + "/" + std::string(file);
}

void ExperimentContext::write_text(std::string_view file, const std::string& text) const {
  if (writes()) write_text_file(results_dir + "/" + std::string(file), text);
}

std::string summary_text(const Experiment& experiment, const toml::table& summary) {
  std::ostringstream text;
  text << "# " << experiment.description << ": measured by exp_" << experiment.name
       << "; see experiments/" << experiment.name << "/README.md\n"
       << summary << '\n';
  return text.str();
}

toml::array toml_array(const std::vector<double>& values) {
  toml::array a;
  for (double x : values) a.push_back(x);
  return a;
}

namespace {

void usage(std::FILE* out, const Experiment& e, std::string_view source_dir) {
  std::fprintf(out,
               "usage: exp_%.*s [--source DIR] RESULTS_DIR\n"
               "%.*s.\n"
               "Writes RESULTS_DIR/summary.toml (the key numbers, compared by the tests with\n"
               "experiments/%.*s/reference.toml) and the data files its plot.gp reads.\n"
               "  --source DIR  the source tree whose experiments/ holds the scenes\n"
               "                (default: %.*s)\n"
               "Exit codes: 0 ok, 1 failure, 2 bad command line.\n",
               static_cast<int>(e.name.size()), e.name.data(),
               static_cast<int>(e.description.size()), e.description.data(),
               static_cast<int>(e.name.size()), e.name.data(), static_cast<int>(source_dir.size()),
               source_dir.data());
}

}  // namespace

int experiment_main(int argc, char** argv, const Experiment& experiment,
                    std::string_view default_source_dir) {
  ExperimentContext context{std::string(default_source_dir), ""};
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(stdout, experiment, default_source_dir);
      return 0;
    }
    if (arg == "--source" && i + 1 < argc) {
      context.source_dir = argv[++i];
    } else if (!arg.empty() && arg[0] != '-' && context.results_dir.empty()) {
      context.results_dir = arg;
    } else {
      std::fprintf(stderr, "exp_%.*s: unexpected argument '%s'\n",
                   static_cast<int>(experiment.name.size()), experiment.name.data(), argv[i]);
      usage(stderr, experiment, default_source_dir);
      return 2;
    }
  }
  if (context.results_dir.empty()) {
    usage(stderr, experiment, default_source_dir);
    return 2;
  }
  struct stat info;
  if (stat(context.results_dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    std::fprintf(stderr, "exp_%.*s: %s: not a directory (create it first)\n",
                 static_cast<int>(experiment.name.size()), experiment.name.data(),
                 context.results_dir.c_str());
    return 2;
  }
  try {
    const toml::table summary = experiment.run(context);
    context.write_text("summary.toml", summary_text(experiment, summary));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_%.*s: %s\n", static_cast<int>(experiment.name.size()),
                 experiment.name.data(), e.what());
    return 1;
  }
  return 0;
}

}  // namespace impact
