// `impact work-precision`, run as a separate process: the table, its sidecar and the figure on
// Figure 4's scene with COR, the orders it reports against the experiment's recipe
// (work_precision_curves.hpp's step_curves and curve_order, recomputed here), the warning on a
// chaotic scene, and bad flags (exit 2, the flag and its value named, nothing written).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "analysis/work_precision_curves.hpp"
#include "cli_support.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kCor075 = kSource + "/experiments/figure4/cor075.toml";

// The number after "key": in the sidecar's JSON, NaN when it is not there or null.
double json_value(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\": ";
  const auto at = json.find(quoted);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + quoted.size(), nullptr);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

bool have_gnuplot() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE(
    "work-precision: Figure 4 with COR gives the table, the sidecar with the experiment's orders "
    "and the figure",
    "[cli][work_precision]") {
  TempDir dir;
  const bool plot = have_gnuplot();
  // The experiment's steps (the default --h) and its methods: the orders must be the
  // experiment's, bit for bit (the same runs, the same fit; the sidecar's numbers round-trip).
  const Result r = dir.run("work-precision " + quote(kCor075) +
                           " --methods direct,moreau_jean --repeat 1 --out wp.csv" +
                           (plot ? " --plot wp.png" : ""));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::vector<std::string> rows = lines_of(slurp(dir / "wp.csv"));
  REQUIRE(rows.size() == 1 + 2 * swept_steps().size());
  CHECK(rows[0] ==
        "method,h,steps,sup_u,l1_v,energy_end,first_impact,cpu_s,cpu_median_s,repetitions,batch,"
        "reference_s,reference_parts_at");
  CHECK(rows[1].rfind("direct,0.10000000000000001,100,", 0) == 0);
  CHECK(rows.back().rfind("moreau_jean,1.0000000000000001e-05,1000000,", 0) == 0);
  CHECK(r.err.find("warning") == std::string::npos);  // Figure 4 is not chaotic

  const std::string json = slurp(dir / "wp.csv.json");
  CHECK_THAT(json, Contains("\"command\": \"impact work-precision\""));
  const Scene scene = load_scene(kCor075);
  const std::vector<Curve> curves =
      step_curves(scene, {"direct", "moreau_jean"}, swept_steps(), std::nullopt);
  for (const Curve& c : curves)
    for (const ErrorMeasure m : kErrorMeasures) {
      const std::string key = c.name + "." + std::string(measure_name(m)) + "_order";
      const OrderFit fit = curve_order(c, m);
      INFO(key);
      if (std::isnan(fit.order))
        CHECK_THAT(json, Contains("\"" + key + "\": null"));
      else
        CHECK(json_value(json, key) == fit.order);
    }
  // The experiment's claim C36 on this scene: both first order in the sup-norm of u.
  CHECK(json_value(json, "moreau_jean.sup_u_order") == Approx(1.0).margin(0.1));
  CHECK(json_value(json, "direct.sup_u_order") == Approx(1.0).margin(0.1));
  if (plot) {
    const std::string png = slurp(dir / "wp.png");
    REQUIRE(png.size() > 8);
    CHECK(png.substr(1, 3) == "PNG");
  }
}

TEST_CASE("work-precision: a chaotic scene warns where its two references part and marks the rows",
          "[cli][work_precision]") {
  // The vibrating table's chaotic regime over 30 s (the experiment stops at 1 s): two references
  // 1e-10 apart in v0 separate as e^(0.6 t), past 1e-3 of the errors before t = 30.
  TempDir dir;
  const Result r = dir.run(
      "work-precision " + quote(kSource + "/experiments/work_precision/table_chaotic.toml") +
      " --set time.T=30 --methods direct --h 1e-2:1e-3:2:log --repeat 1 --out wp.csv");
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Contains("warning: direct at h = 0.001: two references 1e-10 apart in v0"));
  for (const std::string& row : lines_of(slurp(dir / "wp.csv")))
    if (row.rfind("direct,", 0) == 0) CHECK(row.back() != ',');  // reference_parts_at given
}

TEST_CASE(
    "work-precision: without --methods a scene with a force of the state runs the default methods "
    "that can run it and names the others with the reason",
    "[cli][work_precision][regression]") {
  TempDir dir;
  const std::string scene =
      quote(kSource + "/experiments/impact_oscillator/periodic.toml") + " --set time.T=1 ";
  const Result r = dir.run("work-precision " + scene + "--h 1e-2,5e-3 --repeat 1 -o wp.csv");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Contains("impact work-precision: fb_newton left out of the default methods: "
                             "it takes a force of t only, and force.expression reads u or v"));
  std::set<std::string> methods;
  for (const std::string& row : lines_of(slurp(dir / "wp.csv")))
    methods.insert(row.substr(0, row.find(',')));
  CHECK(methods == std::set<std::string>{"method", "direct", "moreau_jean"});
  // --quiet drops the note; a method named in --methods that cannot run the scene is refused.
  CHECK(dir.run("work-precision " + scene + "--h 1e-2,5e-3 --repeat 1 -q -o wp.csv").err.empty());
  const Result named = dir.run("work-precision " + scene + "--methods direct,fb_newton -o x.csv");
  CHECK(named.code == 2);
  CHECK_THAT(named.err, Contains("--methods direct,fb_newton: fb_newton cannot run this scene: it "
                                 "takes a force of t only, and force.expression reads u or v"));
}

TEST_CASE("work-precision: bad flags exit 2 naming the flag, the value and the range",
          "[cli][work_precision]") {
  TempDir dir;
  const std::string scene = quote(kCor075) + " --out wp.csv ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--repeat 0", "--repeat: Value 0 not in range 1 to 1000"},
      {"--h 0:1e-3:3", "--h 0:1e-3:3: h = 0 is out of range: every h must be in (0, T] = (0, 10]"},
      {"--h 1e-2:1e-3:x:log", "--h 1e-2:1e-3:x:log: n = 'x' is not a whole number >= 1"},
      {"--h 1e-3", "--h 1e-3: an order needs at least 2 different steps h"},
      {"--methods direct,exact",
       "--methods direct,exact: 'exact' is not a time-stepper swept "
       "over h; the methods are direct, fb_newton, moreau_jean"},
      {"--methods direct,direct", "--methods direct,direct: direct is named twice"},
      {"--against event_driven",
       "--against event_driven: this scene's force has a closed-form "
       "reference, measured against exact; the allowed value is exact"},
      {"--against lsodar", "--against: lsodar not in {exact,event_driven}"},
      {"--plot wp.txt", "--plot wp.txt: the figure's name must end in .png, .pdf or .svg"},
  };
  for (const auto& [flags, message] : cases) {
    INFO(flags);
    const Result r = dir.run("work-precision " + scene + flags);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains(message));
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("work-precision: --help explains every flag with an example", "[cli][work_precision]") {
  TempDir dir;
  const Result r = dir.run("work-precision --help");
  CHECK(r.code == 0);
  for (const char* flag : {"--methods", "--h", "--against", "--repeat", "--set", "--out", "--plot",
                           "--quiet", "--no-provenance"})
    CHECK_THAT(r.out, Contains(flag));
  CHECK_THAT(r.out, Contains("Example: impact work-precision"));
}
