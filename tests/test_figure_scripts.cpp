// Figures people can read: every experiment's gnuplot script gives each panel a title, axis
// labels with units, a key outside the data (or a stated reason) and axis ranges from the data
// (figure_check_support.hpp says how a script is read). The check is shown to fail on scripts
// broken on purpose, one rule at a time, and on a shipped script with a fixed range added. And
// every figure in figures/ has a vector copy and is shown by a README.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "figure_check_support.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = IMPACT_SOURCE_DIR;

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> check(const std::string& script) {
  figure_check::Checker checker("script.gp");
  checker.run(script);
  return checker.problems();
}

std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const auto& p : problems) out += p + "\n";
  return out;
}

// A panel that passes every rule: the base the broken scripts change one line of.
const std::string kGood = R"(set datafile separator ','
stats 'data.csv' using 1 nooutput
set multiplot layout 1,2 title "A figure"
set title "(a) a panel"
set xlabel "t [s]"
set ylabel "u(t) [m]"
set key outside right top
set xrange [STATS_min : STATS_max]
plot 'data.csv' using 1:2 with lines title "u"
unset multiplot
)";

std::string replaced(const std::string& from, const std::string& to, std::string script = kGood) {
  const auto at = script.find(from);
  REQUIRE(at != std::string::npos);
  return script.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE(
    "every experiment's plot.gp titles its panels, labels its axes with units, keeps its key "
    "off the data and takes its ranges from the data",
    "[figures]") {
  int scripts = 0;
  for (const auto& dir : fs::directory_iterator(kRoot / "experiments")) {
    const auto script = dir.path() / "plot.gp";
    if (!fs::exists(script)) continue;
    ++scripts;
    figure_check::Checker checker(fs::relative(script, kRoot).string());
    checker.run(slurp(script));
    INFO(joined(checker.problems()));
    CHECK(checker.problems().empty());
    CHECK(checker.plots() > 0);
  }
  CHECK(scripts >= 13);
}

TEST_CASE("the figure check passes a script that follows every rule", "[figures]") {
  const auto problems = check(kGood);
  INFO(joined(problems));
  CHECK(problems.empty());
}

TEST_CASE("the figure check names a fixed range, a key on the data, a missing title or unit",
          "[figures]") {
  const auto names = [](const std::string& script, const std::string& what) {
    const auto problems = check(script);
    INFO(joined(problems));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].find(what) != std::string::npos);
    CHECK(problems[0].find("script.gp:") == 0);
  };
  SECTION("a fixed range of literal numbers") {
    names(replaced("[STATS_min : STATS_max]", "[1e-16 : 30]"), "fixed x range");
  }
  SECTION("a fixed range through variables assigned literals") {
    names(replaced("set xrange", "lo = 1e-16; hi = 2 * lo\nset xrange [lo : hi]\n#"),
          "fixed x range");
  }
  SECTION("a key inside the plot") {
    names(replaced("set key outside right top", "set key bottom right box"), "key inside");
  }
  SECTION("gnuplot's default key, top right inside") {
    names(replaced("set key outside right top", "set key noenhanced\nset key default"),
          "key inside");
  }
  SECTION("a panel without a title") {
    names(replaced("set title \"(a) a panel\"", "unset title"), "without a title");
  }
  SECTION("a label without a unit") {
    names(replaced("u(t) [m]", "u(t)"), "ylabel without a unit");
  }
  SECTION("no label") {
    names(replaced("set xlabel \"t [s]\"", "unset xlabel"), "without an xlabel");
  }
  SECTION("a figure without a title") {
    names(replaced("layout 1,2 title \"A figure\"", "layout 1,2"), "multiplot");
  }
  SECTION("a fixed range set by a macro") {
    names(replaced("set xrange [STATS_min : STATS_max]", "r = \"set yrange [0 : 1]\"\n@r"),
          "fixed y range");
  }
}

TEST_CASE(
    "the figure check takes a stated reason for a fixed range or a key inside, not an empty one",
    "[figures]") {
  CHECK(check(replaced("set xrange [STATS_min : STATS_max]",
                       "set xrange [0 : 2 * pi]  # fixed range: the phase is an angle"))
            .empty());
  CHECK(check(replaced("set key outside right top",
                       "# key inside: the top left is empty, errors fall with h\nset key top left"))
            .empty());
  CHECK(check(replaced("set key outside right top", "set key top left  # key inside: empty"))
            .size() == 1);
  CHECK(check(replaced("set xrange [STATS_min : STATS_max]", "set xrange [0 : 1]  # fixed range:"))
            .size() == 1);
  // A panel whose key says nothing (every curve notitle) needs no placement.
  CHECK(check(replaced("title \"u\"", "notitle", replaced("set key outside", "set key top left #")))
            .empty());
}

TEST_CASE("the figure check fails a shipped script with a fixed axis range added", "[figures]") {
  auto script = slurp(kRoot / "experiments/lemma5/plot.gp");
  REQUIRE(check(script).empty());
  const auto at = script.find("\n  plot ");
  REQUIRE(at != std::string::npos);
  script.insert(at, "\n  set yrange [1e-16 : 1]");
  const auto problems = check(script);
  REQUIRE(problems.size() == 1);
  CHECK(problems[0].find("fixed y range") != std::string::npos);
}

TEST_CASE("every figure in figures/ has a vector copy and is shown by a README", "[figures]") {
  std::string readmes = slurp(kRoot / "README.md");
  for (const auto& dir : {kRoot / "experiments", kRoot / "docs"}) {
    if (!fs::exists(dir)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
      if (entry.path().extension() == ".md") readmes += slurp(entry.path());
  }
  int figures = 0;
  for (const auto& entry : fs::directory_iterator(kRoot / "figures")) {
    if (entry.path().extension() != ".png") continue;
    ++figures;
    const auto stem = entry.path().stem().string();
    INFO(stem);
    // The campaign's 1e5 points would make a vector copy of tens of MB: it is a PNG alone.
    auto vector = entry.path();
    if (stem != "error_analysis_campaign")
      CHECK((fs::exists(vector.replace_extension(".svg")) ||
             fs::exists(vector.replace_extension(".pdf"))));
    CHECK(readmes.find("figures/" + stem + ".png") != std::string::npos);
  }
  CHECK(figures > 0);
}
