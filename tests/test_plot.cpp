// `impact plot`: what it draws (runs, events, sweeps, a reference), that no name given to it ever
// becomes a gnuplot command, that it reads within bounds, and that a failed plot leaves an existing
// figure as it was. The reading and thinning of curves (cli/plot_data) are also tested as
// functions.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "cli/plot_data.hpp"
#include "cli_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

const std::string kFigure4 = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";

// A run of Figure 4 with COR (21 impacts, then rest): run.csv, its events ev.csv and the exact
// solution ref.csv.
void write_runs(const TempDir& dir) {
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q -o run.csv --events ev.csv").code == 0);
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q --set method.name=exact -o ref.csv").code == 0);
}

bool is_png(const std::string& path) {
  return slurp(path).substr(1, 3) == "PNG";
}

// A fake gnuplot first on PATH: `body` is its shell script.
std::string fake_gnuplot(const TempDir& dir, const std::string& body) {
  std::filesystem::create_directories(dir / "fake");
  dir.write("fake/gnuplot", "#!/bin/sh\n" + body + "\n");
  std::filesystem::permissions(dir / "fake/gnuplot", std::filesystem::perms::owner_all);
  return "PATH=" + quote(dir / "fake") + ":\"$PATH\" ";
}

}  // namespace

TEST_CASE("plot: a run's CSV, one panel per channel, as png, svg or pdf", "[cli][plot]") {
  TempDir dir;
  write_runs(dir);
  REQUIRE(dir.run("plot run.csv").code == 0);
  CHECK(is_png(dir / "run.png"));
  REQUIRE(dir.run("plot run.csv --out run.svg").code == 0);
  const std::string svg = slurp(dir / "run.svg");
  CHECK_THAT(svg, Contains("<svg") && Contains("u(t) [m]") && Contains("N(t) [m/s^2]"));
  REQUIRE(dir.run("plot run.csv -o run.pdf").code == 0);
  CHECK(slurp(dir / "run.pdf").substr(0, 5) == "%PDF-");
  // Not a CSV of impact, an unknown figure format, a missing file: exit 2, nothing written.
  dir.write("other.csv", "x,y\n1,2\n");
  CHECK_FAILS_CLEANLY(dir, "plot other.csv", 2, Contains("other.csv, line 1: not a CSV of impact"));
  CHECK_FAILS_CLEANLY(dir, "plot run.csv --out run.gif", 2,
                      Contains("run.gif: --out must end in .png, .pdf or .svg"));
  CHECK_FAILS_CLEANLY(dir, "plot missing.csv", 2,
                      Contains("missing.csv: cannot read the CSV: No such file"));
  // One row: a point, drawn without gnuplot's warning about an empty range.
  dir.write("one.csv", "t,u,v\n0,1,2\n");
  const Result one = dir.run("plot one.csv");
  CHECK(one.code == 0);
  CHECK(one.err.empty());
  // A name no channel and no internal variable can have (w could be an internal variable's).
  dir.write("channels.csv", "t,u,2w\n0,1,2\n");
  CHECK_FAILS_CLEANLY(dir, "plot channels.csv", 2,
                      Contains("unknown channel '2w'") && Contains("u, v, N, E, iterations"));
}

TEST_CASE("plot: no name given to it becomes a gnuplot command", "[cli][plot][regression]") {
  TempDir dir;
  write_runs(dir);
  const std::string injected = "x\nsystem(\"touch PWNED\")\ny";
  // The output's name, the CSV's, the reference's and the events' (other spellings: quotes,
  // backquotes, a gnuplot macro).
  CHECK(dir.run("plot run.csv -o " + quote(injected + ".png")).code == 0);
  CHECK(is_png(dir / (injected + ".png")));
  std::filesystem::copy(dir / "run.csv", dir / (injected + ".csv"));
  CHECK(dir.run("plot " + quote(injected + ".csv") + " -o a.svg").code == 0);
  const std::string odd = "b'\"`touch PWNED`@x$(touch PWNED)'\n";
  std::filesystem::copy(dir / "ref.csv", dir / (odd + "ref.csv"));
  std::filesystem::copy(dir / "ev.csv", dir / (odd + "ev.csv"));
  CHECK(dir.run("plot run.csv -o b.svg --against " + quote(odd + "ref.csv") + " --events " +
                quote(odd + "ev.csv"))
            .code == 0);
  CHECK(!std::filesystem::exists(dir / "PWNED"));
  // The names are shown as they are, as text.
  CHECK_THAT(slurp(dir / "a.svg"), Contains("<text>system(\"touch PWNED\")</text>"));
  CHECK_THAT(slurp(dir / "b.svg"), Contains("<text>reference: b'\"`touch PWNED`@x$(touch PWNED)'"));
}

TEST_CASE("plot: what it reads is bounded", "[cli][plot][regression]") {
  TempDir dir;
  // A device that never ends: refused at the first line, instead of read into memory for ever.
  CHECK_FAILS_CLEANLY(dir, "plot /dev/zero -o z.png", 2,
                      Contains("/dev/zero, line 1: longer than 65536 bytes: not a CSV of impact"));
  // Binary data, and a header that never ends.
  constexpr char kBinary[] = "t,u\n0,\0\x01\x02\n";
  dir.write("binary.csv", std::string(kBinary, sizeof kBinary - 1));
  CHECK_FAILS_CLEANLY(dir, "plot binary.csv", 2, Contains("binary.csv, line 2: a NUL byte"));
  dir.write("long.csv", "t" + std::string(70000, 'u') + "\n");
  CHECK_FAILS_CLEANLY(dir, "plot long.csv", 2, Contains("long.csv, line 1: longer than 65536"));
#ifndef __SANITIZE_ADDRESS__  // AddressSanitizer reserves terabytes of address space
  // Three million rows from a pipe, with 300 MB of address space for impact and gnuplot each:
  // read as they stream, and drawn through their extremes.
  const Result r = dir.shell(
      "ulimit -v 300000; { echo t,u; seq 3000000 | sed 's/$/,1/'; } | \"$IMPACT\" plot "
      "/dev/stdin -o long.svg");
  CHECK(r.code == 0);
  CHECK_THAT(slurp(dir / "long.svg"), Contains("3000000 rows, each curve drawn through the first"));
#endif
}

TEST_CASE("plot: a failed gnuplot leaves the figure as it was", "[cli][plot][regression]") {
  TempDir dir;
  write_runs(dir);
  dir.write("run.png", "OLD");
  // A gnuplot that opens the figure named in the script (as gnuplot does), writes part of it and
  // fails; one killed by a signal; one that draws nothing; none on PATH.
  const std::string opens_and_fails =
      fake_gnuplot(dir,
                   "name=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\")\n"
                   "[ -n \"$name\" ] && printf partial > \"$name\"\nprintf partial\nexit 3");
  Result r = dir.shell(opens_and_fails + "\"$IMPACT\" plot run.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("run.csv: gnuplot exited with status 3; run.png is left as it was"));
  CHECK(slurp(dir / "run.png") == "OLD");
  r = dir.shell(fake_gnuplot(dir, "cat >/dev/null; printf partial; kill -9 $$") +
                "\"$IMPACT\" plot run.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("gnuplot was killed by signal 9 (Killed)"));
  CHECK(slurp(dir / "run.png") == "OLD");
  r = dir.shell(fake_gnuplot(dir, "cat >/dev/null") + "\"$IMPACT\" plot run.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("gnuplot exited normally but drew nothing"));
  CHECK(slurp(dir / "run.png") == "OLD");
  r = dir.shell("PATH=/nonexistent \"$IMPACT\" plot run.csv");
  CHECK(r.code == 1);
  CHECK_THAT(r.err, Contains("cannot start gnuplot: No such file or directory"));
  CHECK(slurp(dir / "run.png") == "OLD");
  std::filesystem::remove_all(dir / "fake");
  const std::set<std::string> left = {"ev.csv",  "ref.csv", "ref.csv.json",
                                      "run.csv", "run.png", "run.csv.json"};
  CHECK(dir.entries() == left);  // no temporary
  // A working gnuplot replaces it.
  REQUIRE(dir.run("plot run.csv").code == 0);
  CHECK(is_png(dir / "run.png"));
}

TEST_CASE("plot: CSVs saved with CRLF line ends draw as the originals", "[cli][plot][regression]") {
  TempDir dir;
  write_runs(dir);
  REQUIRE(dir.run("sweep " + quote(kFigure4) + " --vary time.h=1e-3,2e-3 -q -o sw.csv").code == 0);
  std::filesystem::create_directories(dir / "crlf");
  for (const std::string name : {"run.csv", "ev.csv", "sw.csv"}) {
    std::string text = slurp(dir / name), crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    dir.write("crlf/" + name, crlf);
    // The provenance sidecar goes along, as a copy of the file would take it.
    if (std::filesystem::exists(dir / (name + ".json")))
      std::filesystem::copy_file(dir / (name + ".json"), dir / ("crlf/" + name + ".json"));
  }
  for (const std::string args : {"run.csv --events ev.csv", "ev.csv", "sw.csv"}) {
    INFO(args);
    REQUIRE(dir.run("plot " + args + " -o lf.svg").code == 0);
    const Result r = dir.shell("cd crlf && \"$IMPACT\" plot " + args + " -o ../crlf.svg");
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    CHECK(slurp(dir / "crlf.svg") == slurp(dir / "lf.svg"));
  }
}

TEST_CASE("plot: events marked on a run, a reference overlaid, the energy of f(t) named",
          "[cli][plot]") {
  TempDir dir;
  write_runs(dir);
  REQUIRE(dir.run("plot run.csv --events ev.csv --against ref.csv -o both.svg").code == 0);
  const std::string svg = slurp(dir / "both.svg");
  // The reference is named by its method, from its provenance file ref.csv.json.
  CHECK_THAT(svg, Contains("impact (21)") && Contains("stick (1)") && Contains("reference: exact"));
  // An events CSV alone: v before and after each event.
  REQUIRE(dir.run("plot ev.csv -o ev.svg").code == 0);
  CHECK_THAT(slurp(dir / "ev.svg"), Contains("impact: 21, stick: 1, lift: 0"));
  // 20 000 events are drawn through their extremes, and the figure says so.
  REQUIRE(dir.shell("{ echo t,kind,v_before,v_after; seq 20000 | sed 's/$/,impact,-1,0.5/'; } "
                    "> many.csv && \"$IMPACT\" plot many.csv -o many.svg")
              .code == 0);
  CHECK_THAT(slurp(dir / "many.svg"),
             Contains("impact: 20000") && Contains("each curve of more than 8192 points"));
  // E is not v^2/2 - f u when f depends on t: the figure says what it is.
  REQUIRE(dir.run("run " + quote(kFigure4) +
                  " --unset force.f --set 'force.expression=\"-9.8*(1+t/10)\"' -q -o forced.csv")
              .code == 0);
  REQUIRE(dir.run("plot forced.csv -o forced.svg").code == 0);
  const std::string forced = slurp(dir / "forced.svg");
  // (its provenance sidecar says that f depends on t)
  CHECK_THAT(forced, Contains("E = v^2/2 - f(0) u(0) - W(t)"));
  CHECK_THAT(forced, !Contains("v^2/2 - f u"));
  // The wrong CSV in the wrong place: exit 2, nothing written.
  CHECK_FAILS_CLEANLY(dir, "plot run.csv --events ref.csv -o x.png", 2,
                      Contains("ref.csv, line 1: not an events CSV of impact run"));
  CHECK_FAILS_CLEANLY(dir, "plot ev.csv --against ref.csv -o x.png", 2,
                      Contains("--against and --events go with the CSV of a run"));
  dir.write("iterations.csv", "t,iterations\n0,1\n");
  CHECK_FAILS_CLEANLY(dir, "plot run.csv --against iterations.csv -o x.png", 2,
                      Contains("iterations.csv: --against has none of the channels of run.csv"));
}

TEST_CASE("plot: a sweep, one panel per quantity against the varied key", "[cli][plot]") {
  TempDir dir;
  const std::string sweep = "sweep " + quote(kFigure4) + " -q --summary impacts,rest_time ";
  REQUIRE(dir.run(sweep + "--vary time.h=1e-3:1e-2:5:log -o one.csv").code == 0);
  REQUIRE(dir.run("plot one.csv -o one.svg").code == 0);
  CHECK_THAT(slurp(dir / "one.svg"),
             Contains("time.h") && Contains("impacts: impacts") && Contains("5 points"));
  // Two keys: a curve per value of the second; a shard's part.
  REQUIRE(dir.run(sweep + "--vary time.h=1e-3,2e-3 --vary floor.cor=0.5,0.75 -o two.csv").code ==
          0);
  REQUIRE(dir.run("plot two.csv -o two.svg").code == 0);
  CHECK_THAT(slurp(dir / "two.svg"), Contains("floor.cor = 0.5") && Contains("floor.cor = 0.75"));
  REQUIRE(dir.run(sweep + "--vary time.h=1e-3,2e-3,3e-3 --shard 1/2 -o part.csv").code == 0);
  CHECK(dir.run("plot part.csv -o part.svg").code == 0);
  // A failed point is counted and left out; more curves than the figure can key are refused.
  dir.write("failed.csv",
            "time.h,impacts,failure\n0.001,21,\n0.002,,\"did not converge, after 3\"\n");
  REQUIRE(dir.run("plot failed.csv -o failed.svg").code == 0);
  CHECK_THAT(slurp(dir / "failed.svg"), Contains("2 points, of which 1 failed"));
  REQUIRE(dir.run(sweep + "--vary time.h=1e-3 --vary floor.cor=0.1:0.9:9 -o nine.csv").code == 0);
  CHECK_FAILS_CLEANLY(dir, "plot nine.csv -o nine.svg", 2,
                      Contains("more than 8 values of floor.cor"));
  dir.write("bad_key.csv", "time.h;rm,impacts,failure\n1,2,\n");
  CHECK_FAILS_CLEANLY(dir, "plot bad_key.csv", 2, Contains("is not a scene key"));
}

TEST_CASE("plot data: a curve keeps every point up to 2 kBuckets, then every extreme",
          "[plot][property]") {
  using impact::cli::Curve;
  std::mt19937_64 random(17);
  for (const std::int64_t n :
       {std::int64_t{1}, std::int64_t{2 * Curve::kBuckets}, std::int64_t{2 * Curve::kBuckets + 1},
        std::int64_t{100'003}, std::int64_t{1'000'000}}) {
    INFO("n = " << n);
    std::normal_distribution<double> noise;
    std::vector<double> y(static_cast<std::size_t>(n));
    for (double& v : y) v = noise(random);
    Curve curve;
    for (std::int64_t i = 0; i < n; ++i) curve.add(static_cast<double>(i), y[i]);
    const auto points = curve.points();
    const std::int64_t group = curve.per_bucket();
    CHECK(curve.thinned() == (n > static_cast<std::int64_t>(2 * Curve::kBuckets)));
    if (!curve.thinned()) CHECK(points.size() == static_cast<std::size_t>(n));
    CHECK(points.size() <= 8 * Curve::kBuckets);
    // Each group of `group` consecutive points keeps its first, lowest, highest and last.
    std::size_t k = 0;
    bool all_kept = true;
    for (std::int64_t start = 0; start < n; start += group) {
      const std::int64_t end = std::min(n, start + group);
      std::int64_t low = start, high = start;
      for (std::int64_t i = start; i < end; ++i) {
        if (y[i] < y[low]) low = i;
        if (y[i] > y[high]) high = i;
      }
      std::vector<std::int64_t> expected = {start, low, high, end - 1};
      std::sort(expected.begin(), expected.end());
      expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
      for (std::int64_t i : expected) {
        all_kept = all_kept && k < points.size() && points[k].x == static_cast<double>(i) &&
                   points[k].y == y[i];
        ++k;
      }
    }
    CHECK(all_kept);
    CHECK(k == points.size());
  }
}

TEST_CASE("plot data: lines are bounded, CRLF ends dropped, quoted fields kept whole", "[plot]") {
  using impact::cli::CsvLines;
  TempDir dir;
  dir.write("rows.csv", "t,u\r\n0,1\r\n1,2\n2,3\n3,4");
  CsvLines lines(dir / "rows.csv", 2);
  std::string line;
  REQUIRE(lines.next(line));
  CHECK(line == "t,u");
  REQUIRE(lines.next(line));
  CHECK(line == "0,1");
  REQUIRE(lines.next(line));
  CHECK(line == "1,2");
  REQUIRE(lines.next(line));
  CHECK(line == "2,3");
  // Past max_rows + 2 lines (a sweep part's first line, the header, the rows); the last line has
  // no newline.
  CHECK_THROWS_WITH(lines.next(line), Contains("rows.csv, line 5: more than 2 rows"));
  CHECK(impact::cli::split_fields("1,,\"a, \"\"b\"\"\"") ==
        std::vector<std::string>{"1", "", "a, \"b\""});
  double x = 0;
  CHECK(impact::cli::parse_number("nan", x));
  CHECK(std::isnan(x));
  CHECK(!impact::cli::parse_number("1e", x));
  CHECK(!impact::cli::parse_number("", x));
  CHECK(!impact::cli::parse_number("1 ", x));
}
