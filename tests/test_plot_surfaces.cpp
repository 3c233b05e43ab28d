// `impact plot` against everything the other commands write: the CSV of `impact run` for each
// scene feature (internal variables included, a panel each), its --events (with the internal
// variables at each event), `impact sweep` with every quantity, and the table of
// `impact work-precision`. And what plot must never do: replace a file it draws, or wait on a
// named pipe where the CSV's optional provenance file would be.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

const std::string kFigure4 = std::string(IMPACT_SOURCE_DIR) + "/experiments/figure4/cor075.toml";

// A drop onto the floor with COR 0.2 under a pull that decays with z, and a second internal
// variable that follows it: impacts, a rest, and a lift-off at ln 3 (test_internal.cpp).
const std::string kInternal =
    "[initial]\nu0 = 0.2\nv0 = 0.0\n[floor]\ncor = 0.2\n[force]\nexpression = \"5 - 15 * z\"\n"
    "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n"
    "[[internal]]\nname = \"bond\"\ninitial = 0.5\nrate = \"-bond * z\"\n"
    "[time]\nT = 2.0\nh = 0.001\n[method]\nname = \"event_driven\"\n"
    "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"z\", \"bond\"]\n";

// One scene per feature: a constant force with and without COR, a harmonic force, an
// expression of t, a force of the state, internal variables.
struct Feature {
  std::string name, scene, method;
};
std::vector<Feature> features() {
  const std::string drop = "[initial]\nu0 = 1.0\nv0 = 0.0\n[time]\nT = 1.5\nh = 0.001\n";
  return {
      {"constant force, COR", drop + "[floor]\ncor = 0.5\n[force]\nf = -9.81\n", "direct"},
      {"constant force, no COR", drop + "[force]\nf = -9.81\n", "fb_newton"},
      {"harmonic force",
       drop + "[floor]\ncor = 0.5\n[force]\nf = -9.81\namplitude = 3.0\n" + "omega = 20.0\n",
       "moreau_jean"},
      {"expression of t", drop + "[floor]\ncor = 0.5\n[force]\nexpression = \"-9.81 + sin(3*t)\"\n",
       "event_driven"},
      {"force of the state", drop + "[floor]\ncor = 0.5\n[force]\nexpression = \"-9.81 - v\"\n",
       "direct"},
      {"internal variables", kInternal, "event_driven"},
  };
}

}  // namespace

TEST_CASE("plot: every CSV of run, --events, sweep and work-precision draws, for every feature",
          "[cli][plot]") {
  TempDir dir;
  for (const Feature& f : features()) {
    INFO(f.name);
    dir.write("s.toml", f.scene);
    const std::string method = " --set method.name=" + f.method;
    // Every channel the method writes, the events, a sweep with every quantity.
    const std::string channels =
        f.method == "fb_newton" ? R"(["u", "v", "N", "E", "iterations"])" : "";
    REQUIRE(dir.run("run s.toml -q -o run.csv --events ev.csv" + method +
                    (channels.empty() ? "" : " --set 'output.channels=" + channels + "'"))
                .code == 0);
    for (const std::string csv : {"run.csv", "ev.csv"}) {
      const Result r = dir.run("plot " + csv + " -o fig.svg");
      INFO(csv << ": " << r.err);
      CHECK(r.code == 0);
    }
    REQUIRE(dir.run("sweep s.toml -q -o sweep.csv --vary floor.cor=0.1,0.3" + method +
                    " --summary u_T,v_T,E_T,contact_steps,impacts,first_impact_time,rest_time,"
                    "max_u,iterations,wall_s")
                .code == 0);
    const Result sweep = dir.run("plot sweep.csv -o fig.svg");
    INFO(sweep.err);
    CHECK(sweep.code == 0);
  }
  // The internal variables: a panel each in the run, in its events and in the sweep's z at T.
  dir.write("s.toml", kInternal);
  REQUIRE(dir.run("run s.toml -q -o run.csv --events ev.csv").code == 0);
  REQUIRE(dir.run("plot run.csv -o run.svg").code == 0);
  CHECK_THAT(slurp(dir / "run.svg"),
             Contains("z(t) (internal variable)") && Contains("bond(t) (internal variable)"));
  REQUIRE(slurp(dir / "ev.csv").starts_with("t,kind,v_before,v_after,z,bond\n"));
  REQUIRE(dir.run("plot ev.csv -o ev.svg").code == 0);
  CHECK_THAT(slurp(dir / "ev.svg"), Contains("impact: 13, stick: 1, lift: 1") &&
                                        Contains("bond (internal variable) at the event"));
  REQUIRE(dir.run("plot run.csv --events ev.csv -o both.svg").code == 0);
  dir.write("z_T.csv", "floor.cor,u_T,z_T,failure\n0.1,1,0.5,\n0.2,2,0.25,\n");
  REQUIRE(dir.run("plot z_T.csv -o z_T.svg").code == 0);
  CHECK_THAT(slurp(dir / "z_T.svg"), Contains("z (internal variable) at the last grid time"));
  // The errors against exact and the reference's time, which plot used to refuse.
  REQUIRE(dir.run("sweep " + quote(kFigure4) +
                  " -q -o err.csv --vary time.h=1e-3,2e-3 --against exact --summary "
                  "err_u_sup,err_v_l1,err_E_T,err_first_impact,reference_s")
              .code == 0);
  REQUIRE(dir.run("plot err.csv -o err.svg").code == 0);
  CHECK_THAT(slurp(dir / "err.svg"), Contains("reference_s: wall time of the reference"));
  // The table of work-precision, drawn as its --plot draws it.
  REQUIRE(dir.run("work-precision " + quote(kFigure4) +
                  " -q --methods direct,moreau_jean --h 1e-2,5e-3 --repeat 1 -o wp.csv")
              .code == 0);
  REQUIRE(dir.run("plot wp.csv -o wp.svg").code == 0);
  CHECK_THAT(slurp(dir / "wp.svg"), Contains("work against precision: wp.csv") &&
                                        Contains("moreau_jean") && Contains("step h [s]"));
  // What is not one of these: exit 2, nothing written.
  dir.write("bad_events.csv", "t,kind,v_before,v_after,2z\n0,impact,-1,1,0\n");
  CHECK_FAILS_CLEANLY(dir, "plot bad_events.csv", 2,
                      Contains("'2z' after v_after is not the name of an internal variable"));
  CHECK_FAILS_CLEANLY(dir, "plot wp.csv --events ev.csv -o x.svg", 2,
                      Contains("not of impact work-precision"));
  dir.write("bad_wp.csv", slurp(dir / "wp.csv") + "direct,x,1,1,1,1,1,1,1,1,1,1,\n");
  CHECK_FAILS_CLEANLY(dir, "plot bad_wp.csv", 2, Contains("h = 'x' is not a number"));
}

TEST_CASE("plot: the figure never replaces a file it draws, whatever the name or link",
          "[cli][plot][regression]") {
  TempDir dir;
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q -o run.csv --events ev.csv").code == 0);
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q --set method.name=exact -o ref.csv").code == 0);
  // Inputs named like figures, as a user may name anything.
  for (const std::string name : {"run", "ev", "ref"})
    std::filesystem::copy_file(dir / (name + ".csv"), dir / (name + ".svg"));
  std::filesystem::create_directories(dir / "sub");
  std::filesystem::create_symlink("run.csv", dir / "link.svg");
  std::filesystem::create_symlink("ref.csv", dir / "ref_link.png");
  std::filesystem::create_symlink("ev.csv", dir / "ev_link.pdf");
  std::filesystem::create_symlink("run.csv.json", dir / "sidecar.svg");
  std::filesystem::create_hard_link(dir / "run.csv", dir / "hard.svg");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plot run.svg -o run.svg", "--out names the CSV (run.svg)"},
      {"plot run.svg -o ./sub/../run.svg", "--out names the CSV (run.svg)"},
      {"plot run.svg -o " + quote(dir / "run.svg"), "--out names the CSV"},
      {"plot run.csv --against ref.svg -o ref.svg", "--out names --against (ref.svg)"},
      {"plot run.csv --events ev.svg -o ev.svg", "--out names --events (ev.svg)"},
      {"plot run.csv -o link.svg", "--out names the CSV (run.csv)"},
      {"plot run.csv -o hard.svg", "--out names the CSV (run.csv)"},
      {"plot run.csv --against ref.csv -o ref_link.png", "--out names --against (ref.csv)"},
      {"plot run.csv --events ev.csv -o ev_link.pdf", "--out names --events (ev.csv)"},
      {"plot run.csv -o sidecar.svg", "--out names the CSV's provenance (run.csv.json)"},
  };
  std::vector<std::string> before;
  for (const std::string f :
       {"run.csv", "run.svg", "ref.csv", "ref.svg", "ev.csv", "ev.svg", "run.csv.json"})
    before.push_back(slurp(dir / f));
  for (const auto& [args, says] : cases) CHECK_FAILS_CLEANLY(dir, args, 2, Contains(says));
  std::size_t i = 0;
  for (const std::string f :
       {"run.csv", "run.svg", "ref.csv", "ref.svg", "ev.csv", "ev.svg", "run.csv.json"}) {
    INFO(f);
    CHECK(slurp(dir / f) == before[i++]);
  }
  // Another name is drawn.
  CHECK(dir.run("plot run.svg --against ref.svg --events ev.svg -o fig.svg").code == 0);
}

TEST_CASE("plot: a CSV's .json that is not a regular file is skipped, not waited on",
          "[cli][plot][regression]") {
  TempDir dir;
  REQUIRE(dir.run("run " + quote(kFigure4) + " -q --no-provenance -o run.csv").code == 0);
  // A named pipe without a writer (read, it would wait for ever: `timeout` ends the wait and the
  // check fails), a directory, a device, a dangling link.
  const std::vector<std::pair<std::string, std::string>> sidecars = {
      {"fifo", "mkfifo f.csv.json"},
      {"directory", "mkdir d.csv.json"},
      {"device", "ln -s /dev/zero z.csv.json"},
      {"dangling link", "ln -s nowhere n.csv.json"},
  };
  for (const auto& [what, make] : sidecars) {
    INFO(what);
    const std::string csv = make.substr(make.size() - 10, 5);  // f.csv, d.csv, ...
    REQUIRE(dir.shell("cp run.csv " + csv + " && " + make).code == 0);
    const Result r = dir.shell("timeout 20 \"$IMPACT\" plot " + csv + " -o fig.svg");
    INFO(r.err);
    CHECK(r.code == 0);
    // Without a provenance file the figure names both readings of E.
    CHECK_THAT(slurp(dir / "fig.svg"), Contains("with a force f(t)"));
  }
}
