// `impact --help` and `impact run --help`, run as a separate process (IMPACT_CLI): short at the
// top, complete under run, within 80 columns, and listing the key tables the reader checks
// against (scene_keys.hpp), so that the help and the reader cannot disagree.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/methods/capabilities.hpp"
#include "scene/scene_keys.hpp"

using Catch::Contains;

using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;

// Columns of a line on a terminal: UTF-8 characters, not bytes.
std::size_t columns(const std::string& line) {
  return static_cast<std::size_t>(std::count_if(line.begin(), line.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

// Every line of a help text fits 80 columns.
void check_width(const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    INFO(line);
    CHECK(columns(line) <= 80);
  }
}

// The rows of the key tables in `impact run --help`, each joined with the lines it wraps into
// (indented past the default column).
std::vector<std::string> help_rows(const std::string& help) {
  std::vector<std::string> rows;
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(std::string(34, ' '), 0) == 0 && !rows.empty())
      rows.back().append(" ").append(line.substr(line.find_first_not_of(' ')));
    else
      rows.push_back(line);
  }
  return rows;
}

// The row of `key` under the heading line that starts with `section`, or "".
std::string help_row(const std::vector<std::string>& rows, const std::string& section,
                     const std::string& key) {
  bool in = false;
  for (const auto& row : rows) {
    if (row.rfind(section, 0) == 0)
      in = true;
    else if (in && row.find_first_not_of(' ') == 2 && row.back() == ':' && section.size() > 2)
      in = false;  // the next method's heading
    if (in && row.find(" " + key + " ") != std::string::npos &&
        row.find_first_not_of(' ') == row.find(key))
      return row;
  }
  return "";
}

}  // namespace

TEST_CASE("help: --help is short and points at run --help, which lists the options and methods",
          "[help]") {
  TempDir dir;
  const Result top = dir.run("--help");
  CHECK(top.code == 0);
  CHECK_THAT(top.out, Contains("impact run --help") && Contains("run") && Contains("Exit codes"));
  // Four subcommands (run, sweep, plot, work-precision), the options and the exit codes: one
  // screen.
  CHECK(std::count(top.out.begin(), top.out.end(), '\n') <= 24);
  check_width(top.out);
  const Result run = dir.run("run --help");
  CHECK(run.code == 0);
  for (const char* option : {"--set", "--unset", "--out", "--quiet"})
    CHECK_THAT(run.out, Contains(option));
  for (const auto& m : impact::methods()) CHECK_THAT(run.out, Contains(std::string(m.name)));
  CHECK_THAT(run.out, Contains("Exit codes"));
  check_width(run.out);
  CHECK(dir.entries().empty());
  // No subcommand, or an unknown option, is a usage error.
  CHECK(dir.run("").code == 2);
  CHECK(dir.run("run " + quote(kSource + "/experiments/figure3/no_cor.toml") + " --bogus").code ==
        2);
}

TEST_CASE("help: run --help lists every key with its default and range, from the reader's table",
          "[help]") {
  TempDir dir;
  const Result r = dir.run("run --help");
  REQUIRE(r.code == 0);
  const auto rows = help_rows(r.out);
  const auto check_row = [&](const impact::KeySpec& spec, const std::string& section,
                             const std::string& name, const impact::Scene& defaults) {
    const std::string row = help_row(rows, section, name);
    INFO(name << ": '" << row << "'");
    CHECK_FALSE(row.empty());
    CHECK_THAT(row, Contains(spec.required ? std::string("required")
                             : spec.get    ? impact::show_value(spec.get(defaults))
                                           : std::string("none")));
    if (!spec.range.text().empty()) CHECK_THAT(row, Contains(spec.range.text()));
    if (spec.choices)
      for (auto choice : spec.choices()) CHECK_THAT(row, Contains(std::string(choice)));
    CHECK_THAT(row, Contains(std::string(spec.also)) && Contains(std::string(spec.meaning)));
  };
  for (const auto& spec : impact::scene_keys())
    check_row(spec, "Scene keys", std::string(spec.table) + "." + std::string(spec.key),
              impact::Scene{});
  for (const auto& spec : impact::method_keys()) {
    impact::Scene defaults;
    defaults.method = impact::find_method(spec.method())->defaults;
    check_row(spec, "  " + std::string(spec.method()) + ":", std::string(spec.key), defaults);
  }
  // What the table says is what the paper and docs/scenes.md say (a few by hand).
  CHECK_THAT(help_row(rows, "  fb_newton:", "epsilon"), Contains("1e-15") && Contains("(0, 1]"));
  CHECK_THAT(help_row(rows, "  fb_newton:", "max_iterations"),
             Contains(" 50 ") && Contains("integer in [1, 10000]"));
  CHECK_THAT(help_row(rows, "  penalty:", "stiffness"), Contains("1e+06"));
  CHECK_THAT(help_row(rows, "  penalty:", "stepper"), Contains("'rk8pd'") && Contains("bsimp"));
  CHECK_THAT(help_row(rows, "  moreau_jean:", "theta"), Contains("0.5") && Contains("[0, 1]"));
  CHECK_THAT(help_row(rows, "  direct:", "free_flight"), Contains("'closed_form'"));
  CHECK_THAT(help_row(rows, "Scene keys", "floor.phi"), Contains("0.0"));
  CHECK_THAT(help_row(rows, "Scene keys", "output.channels"), Contains("['u', 'v']"));
  CHECK_THAT(help_row(rows, "Scene keys", "time.h"), Contains("> 0, <= time.T"));
  CHECK_THAT(help_row(rows, "  exact:", "max_events"),
             Contains(" 0 ") && Contains("automatic, 1e6 plus 1000 per grid step"));
  CHECK_THAT(help_row(rows, "  event_driven:", "max_ode_steps"), Contains("integer in [0, "));
  // The channels, and which methods count iterations.
  for (const char* channel : {"u", "v", "N", "E", "iterations"})
    CHECK_THAT(r.out, Contains("\n  " + std::string(channel) + " "));
  std::string flat;  // the help with its line breaks and indentation as single spaces
  for (char c : r.out)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!flat.empty() && flat.back() != ' '))
      flat += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  CHECK_THAT(flat, Contains("iterations Newton or ODE-driver iterations of the steps since the "
                            "previous row (fb_newton, penalty only)"));
}

TEST_CASE("help and version that cannot be written exit 1", "[help][cli][regression]") {
  TempDir dir;
  // A full device takes nothing: the text is lost, and the exit code says so (it used to be 0).
  for (const std::string args : {"--help", "run --help", "sweep --help", "--version"}) {
    INFO(args);
    const Result r = dir.shell("\"$IMPACT\" " + args + " > /dev/full");
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("standard output: write failed"));
    CHECK(dir.run(args).code == 0);
  }
}
