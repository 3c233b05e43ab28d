// What `impact plot` asks gnuplot to draw, read from the script itself (a stand-in gnuplot on PATH
// keeps it): panels with the same fixed margins, so that their t axes line up; one key for the
// figure whose curves are named by their method; titles in words, not the paper's equation
// numbers; axis ranges that span the data, not the next decade.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

const std::string kFigure4 = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";

// Runs `impact plot ARGS` with a gnuplot that keeps its script in script.gp and draws one byte;
// returns the script.
std::string plot_script(const TempDir& dir, const std::string& args) {
  std::filesystem::create_directories(dir / "fake");
  dir.write("fake/gnuplot", "#!/bin/sh\ncat > script.gp\nprintf x\n");
  std::filesystem::permissions(dir / "fake/gnuplot", std::filesystem::perms::owner_all);
  std::filesystem::remove(dir / "script.gp");
  const Result r = dir.shell("PATH=" + quote(dir / "fake") + ":\"$PATH\" \"$IMPACT\" plot " + args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  return slurp(dir / "script.gp");
}

std::vector<std::string> matches(const std::string& text, const std::string& pattern) {
  std::vector<std::string> out;
  const std::regex re(pattern);
  for (std::sregex_iterator m(text.begin(), text.end(), re), end; m != end; ++m)
    out.push_back(m->size() > 1 ? (*m)[1].str() : (*m)[0].str());
  return out;
}

// The statements that draw something (a panel or the key), each with the settings before it.
std::vector<std::string> plot_sections(const std::string& script) {
  std::vector<std::string> sections;
  std::string current;
  bool in_plot = false;
  std::size_t begin = script.find("set multiplot");
  while (begin < script.size()) {
    const std::size_t end = std::min(script.find('\n', begin), script.size());
    const std::string line = script.substr(begin, end - begin);
    begin = end + 1;
    current += line + "\n";
    in_plot = in_plot || line.starts_with("plot ");
    if (in_plot && !line.ends_with("\\")) {
      sections.push_back(current);
      current.clear();
      in_plot = false;
    }
  }
  return sections;
}

// The plot statement that ends a section.
std::string plot_statement(const std::string& section) {
  const auto at = section.rfind("\nplot ");
  return at == std::string::npos ? section : section.substr(at + 1);
}

}  // namespace

TEST_CASE("plot: every panel of a run has the same fixed margins, so their t axes line up",
          "[cli][plot][regression]") {
  TempDir dir;
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q -o run.csv --events ev.csv").code == 0);
  const std::string script = plot_script(dir, "run.csv --events ev.csv");
  CHECK(script.find("layout") == std::string::npos);  // gnuplot's layout sizes margins by tics
  const auto sections = plot_sections(script);
  REQUIRE(sections.size() == 5);  // u, v, N, E and the key
  std::set<std::string> left, right;
  for (std::size_t p = 0; p + 1 < sections.size(); ++p) {
    const auto l = matches(sections[p], "set lmargin at screen ([0-9.]+)");
    const auto r = matches(sections[p], "set rmargin at screen ([0-9.]+)");
    REQUIRE(l.size() == 1);
    REQUIRE(r.size() == 1);
    left.insert(l[0]);
    right.insert(r[0]);
    // t from the first row to the last, in every panel.
    CHECK_THAT(sections[p], Contains("set xrange [0:10]"));
  }
  CHECK(left.size() == 1);
  CHECK(right.size() == 1);
}

TEST_CASE(
    "plot: one key for the figure, naming the run's and the reference's method from their "
    "provenance, else their files",
    "[cli][plot][regression]") {
  TempDir dir;
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q -o run.csv --events ev.csv").code == 0);
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q --set method.name=exact -o ref.csv").code == 0);
  const std::string script = plot_script(dir, "run.csv --against ref.csv --events ev.csv");
  const auto sections = plot_sections(script);
  REQUIRE(sections.size() == 5);
  for (std::size_t p = 0; p + 1 < sections.size(); ++p)
    CHECK(matches(plot_statement(sections[p]), " title ").empty());  // no key of their own
  const std::string& key = sections.back();
  CHECK_THAT(key, Contains("title 'direct'") && Contains("title 'reference: exact'") &&
                      Contains("title 'impact (21)'"));
  CHECK(key.find("ARG") == std::string::npos);
  CHECK(matches(key, "title 'direct'").size() == 1);  // once, though four panels draw it
  // Without the provenance files: the file names, as gnuplot's arguments.
  std::filesystem::remove(dir / "run.csv.json");
  std::filesystem::remove(dir / "ref.csv.json");
  const std::string bare = plot_script(dir, "run.csv --against ref.csv");
  CHECK_THAT(plot_sections(bare).back(),
             Contains("title ARG1") && Contains("title 'reference: ' . ARG2"));
  // A provenance file naming no method of the table is not believed.
  dir.write("run.csv.json", "{\n  \"method\": \"x'; system('touch PWNED')\",\n}\n");
  CHECK_THAT(plot_sections(plot_script(dir, "run.csv --against ref.csv")).back(),
             Contains("title ARG1"));
  CHECK(!std::filesystem::exists(dir / "PWNED"));
}

TEST_CASE("plot: the titles say what E and N_scheme are in words, not by the paper's numbers",
          "[cli][plot][regression]") {
  TempDir dir;
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q -o run.csv").code == 0);
  std::string script = plot_script(dir, "run.csv");
  CHECK_THAT(script, Contains("kinetic plus potential energy per unit mass under the constant"));
  CHECK(script.find("(3-1)") == std::string::npos);
  std::filesystem::remove(dir / "run.csv.json");  // unknown force: both energies named
  script = plot_script(dir, "run.csv");
  CHECK_THAT(script, Contains("W the work of f since t = 0"));
  CHECK(script.find("(3-1)") == std::string::npos);
  // N_scheme: its own colour and a line that says how it differs from N.
  REQUIRE(dir.run("run " + quote(kFigure4) +
                  " -q --set method.name=fb_newton --set 'output.channels=[\"N\",\"N_scheme\"]' "
                  "-o scheme.csv")
              .code == 0);
  script = plot_script(dir, "scheme.csv");
  CHECK_THAT(script, Contains("N_scheme: the scheme''s solve, before a COR''s rebound"));
  const auto sections = plot_sections(script);
  REQUIRE(sections.size() == 2);
  CHECK_THAT(sections[0], Contains("impulses lw 1.5 lc rgb '#0072B2'"));
  CHECK_THAT(sections[1], Contains("impulses lw 1.5 lc rgb '#D55E00'") &&
                              Contains("set ylabel 'N_scheme(t) [m/s^2]'"));
}

TEST_CASE(
    "plot: the work-precision figure has one key for its eight panels and its axes span the data",
    "[cli][plot][work_precision][regression]") {
  TempDir dir;
  REQUIRE(dir.run("work-precision " + quote(kFigure4) +
                  " --methods direct,moreau_jean --h 1e-2,1e-3 --repeat 1 -q -o wp.csv")
              .code == 0);
  const std::string script = plot_script(dir, "wp.csv");
  const auto sections = plot_sections(script);
  REQUIRE(sections.size() == 9);
  for (std::size_t p = 0; p + 1 < sections.size(); ++p)
    CHECK(matches(plot_statement(sections[p]), " title ").empty());
  CHECK(matches(sections.back(), "title 'direct'").size() == 1);
  CHECK(matches(sections.back(), "title 'moreau_jean'").size() == 1);
  // The four panels against h: the data's 1e-3 .. 1e-2 with a margin, not gnuplot's 1e-3 .. 0.1.
  for (std::size_t p = 4; p < 8; ++p) {
    const auto range = matches(sections[p], "set xrange \\[([^:]+):([^\\]]+)\\]");
    REQUIRE(range.size() == 1);
    const auto bounds = matches(sections[p], "set xrange \\[[^:]+:([^\\]]+)\\]");
    CHECK(std::stod(bounds.at(0)) < 0.0125);
    CHECK(std::stod(range.at(0)) > 0.0008);
  }
}
