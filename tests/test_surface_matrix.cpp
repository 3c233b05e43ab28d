// Every scene feature against every surface that carries a run to a user: the surface handles it
// (its columns are named as the scene names them, and it agrees with the library) or refuses it
// with exit 2. The table below says which, cell by cell. A feature the capability table gains, a
// subcommand or an output option `impact` gains, or a function the Python module gains, without a
// row or column here, fails the test.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/output/channels.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "output_support.hpp"
#include "scene/read_scene.hpp"

using namespace impact;
using namespace impact::testing;

namespace {

// The bits of a double, to compare two bit for bit.
std::uint64_t same_bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// A new capability is a new column of the capability table (capabilities.hpp): a feature a scene
// can ask for, or a property of a method. Either way it needs a row here (kFeatures) or a word in
// kNotFeatures.
static_assert(sizeof(Capabilities) == 11,
              "a capability was added or removed: give it a row in kFeatures of "
              "test_surface_matrix.cpp (or say in kNotFeatures why it is none)");
[[maybe_unused]] constexpr const char* kNotFeatures =
    "iterations_channel and scheme_force_channel are channels a method writes (the run rows "
    "check them through the CSV); reference, energy_bound and exact_events are properties of a "
    "method, not of a scene; a harmonic force has a row but no column, as every method takes it";

struct Feature {
  std::string name, scene;
};

const std::string kHead =
    "[initial]\nu0 = 0.3\nv0 = 0.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = \"direct\"\n";

const std::vector<Feature> kFeatures = {
    {"constant f",
     kHead + "[force]\nf = -9.81\n[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n"},
    {"COR", kHead + "[force]\nf = -9.81\n[floor]\ncor = 0.8\n"
                    "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"N_scheme\"]\n"},
    {"harmonic", kHead + "[force]\nf = -9.81\namplitude = 5.0\nomega = 20.0\n[floor]\ncor = 0.8\n"
                         "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n"},
    {"expression of t", kHead + "[force]\nexpression = \"-9.81 + 5 * sin(20 * t)\"\n"
                                "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n"},
    {"state force", kHead +
                        "[force]\nexpression = \"-9.81 - 20 * (u - 0.3) - 0.5 * v\"\n"
                        "[floor]\ncor = 0.8\n[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n"},
    {"internal variables",
     kHead + "[force]\nexpression = \"-9.81 + 5 * beta - 0.5 * v\"\n[floor]\ncor = 0.8\n"
             "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"
             "[[internal]]\nname = \"beta\"\ninitial = 1.0\nrate = \"-2 * beta + u\"\n"
             "[[internal]]\nname = \"D\"\ninitial = 0.0\nrate = \"v^2\"\n"},
    {"linear force", kHead + "[force]\nf = -9.81\namplitude = 5.0\nomega = 20.0\n"
                             "linear = { k = 20.0, c = 0.5, u_eq = 0.3 }\n[floor]\ncor = 0.8\n"
                             "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\"]\n"},
    // The bonding field, with event_driven and with a time-stepper (the methods that take it:
    // direct, moreau_jean, exact, event_driven).
    {"bonding field",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"event_driven\"\n[force]\nf = -9.81\n[floor]\ncor = 0.9\n[bonding]\ngamma = 100.0\n"
     "L = 0.03\neps_a = 0.05\nbeta0 = 1.0\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    {"bonding field, direct",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"direct\"\n[force]\nf = -9.81\n[floor]\ncor = 0.9\n[bonding]\ngamma = 100.0\n"
     "L = 0.03\neps_a = 0.05\nbeta0 = 1.0\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    // The Frémond form of the field (bonding.form, bonding.b), with both kinds of method.
    {"bonding field, fremond",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"event_driven\"\n[force]\nf = -9.81\n[floor]\ncor = 0.9\n[bonding]\ngamma = 100.0\n"
     "L = 0.03\neps_a = 0.05\nbeta0 = 1.0\nform = \"fremond\"\nb = 0.01\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    {"bonding field, fremond, moreau_jean",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"moreau_jean\"\n[force]\nf = -9.81\n[floor]\ncor = 0.9\n[bonding]\ngamma = 100.0\n"
     "L = 0.03\neps_a = 0.05\nbeta0 = 1.0\nform = \"fremond\"\nb = 0.01\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    // The field under a force of time (the vibrating table seen from the table), as the harmonic
    // part with event_driven and as an expression of t with a time-stepper.
    {"bonding field, harmonic",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"event_driven\"\n[force]\nf = -9.81\namplitude = 5.0\nomega = 20.0\n[floor]\ncor = 0.9\n"
     "[bonding]\ngamma = 100.0\nL = 0.03\neps_a = 0.05\nbeta0 = 1.0\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    {"bonding field, expression of t, direct",
     "[initial]\nu0 = 0.0\nv0 = 1.0\n[time]\nT = 0.5\nh = 1e-3\n[method]\nname = "
     "\"direct\"\n[force]\nexpression = \"-9.81 + 5 * sin(20 * t)\"\n[floor]\ncor = 0.9\n"
     "[bonding]\ngamma = 100.0\nL = 0.03\neps_a = 0.05\nbeta0 = 1.0\n"
     "[output]\nchannels = [\"u\", \"v\", \"N\", \"E\", \"beta\", \"D\"]\n"},
    // The two-mass chain is a library model: no scene key gives it, so every surface that reads a
    // scene refuses one that asks for it.
    {"the chain", kHead + "[chain]\nm1 = 1.0\n"},
};

enum class Expect { handles, refuses };

struct Surface {
  std::string name;
  // Runs the surface on the scene in dir/s.toml; returns "" when it handled the feature right,
  // "refused" when it exited 2 naming the scene, else what went wrong.
  std::function<std::string(const TempDir&, const Scene*)> check;
};

// The library's rows of a scene (run_scene, as `impact run` calls it), formatted as the CSV.
std::string library_csv(const Scene& scene, std::vector<Event>* events = nullptr) {
  AnyStepper stepper = make_stepper(scene);
  std::string text = "t";
  for (Channel c : scene.output.channels) {
    text += ',';  // appended, not "," + std::string: GCC 12's -Wrestrict misfires on that here
    text += channel_name(c, scene.model);
  }
  text += "\n";
  RunOutputs outputs;
  outputs.rows = [&](const OutputRow& row) {
    text += round_trip(scene.grid.t(row.l));
    for (Channel c : scene.output.channels) {
      text += ',';  // appended piece by piece: GCC 12 reports a false -Wrestrict for "," + ...
      text += c == Channel::iterations ? std::to_string(row.iterations)
                                       : round_trip(channel_value(row, c));
    }
    text += "\n";
  };
  if (events) outputs.events = [&](const Event& e) { events->push_back(e); };
  run_scene(scene, stepper, outputs);
  return text;
}

std::string refused_or(const Result& r, const std::string& what) {
  if (r.code == 2 && r.err.find("s.toml") != std::string::npos) return "refused";
  return what + " (exit " + std::to_string(r.code) + "): " + r.err;
}

std::string run_csv(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run("run s.toml -q -o run.csv");
  if (r.code != 0 || !scene) return refused_or(r, "impact run");
  const std::string csv = slurp(dir / "run.csv");
  return csv == library_csv(*scene) ? "" : "the CSV differs from the library's rows";
}

std::string events(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run("run s.toml -q -o run.csv --events ev.csv");
  if (r.code != 0 || !scene) return refused_or(r, "impact run --events");
  std::vector<Event> library;
  library_csv(*scene, &library);
  std::string want = "t,kind,v_before,v_after";
  // The model's internal variables, or a bonded model's beta and D.
  const std::vector<std::string> variables = event_variables(scene->model);
  for (const std::string& name : variables) {
    want += ',';  // appended, as in library_csv
    want += name;
  }
  want += "\n";
  for (const Event& e : library) {
    want += round_trip(e.t) + "," + std::string(event_name(e.kind)) + "," + round_trip(e.v_before) +
            "," + round_trip(e.v_after);
    for (std::size_t i = 0; i < variables.size(); ++i) {
      want += ',';  // appended, as in library_csv
      want += round_trip(e.internal[i]);
    }
    want += "\n";
  }
  return slurp(dir / "ev.csv") == want ? "" : "the events differ from the library's";
}

std::string sweep(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run("sweep s.toml -q -o sweep.csv --vary time.h=1e-3,5e-4");
  if (r.code != 0 || !scene) return refused_or(r, "impact sweep");
  // The rows without their last column, failure (empty: no point failed).
  std::string text = slurp(dir / "sweep.csv");
  for (std::size_t at; (at = text.find(",\n")) != std::string::npos;) text.erase(at, 1);
  text.replace(text.find(",failure"), 8, "");
  const Table table = read_table(text);
  for (std::size_t p = 0; p < 2; ++p) {
    Scene point = *scene;
    point.grid = Grid::covering(point.T, p == 0 ? 1e-3 : 5e-4);
    const PointSummary s = summarize(point, false).summary;
    std::map<std::string, double> want{
        {"u_T", s.final.u}, {"v_T", s.final.v}, {"E_T", s.energy_final}};
    for (std::size_t i = 0; i < scene->model.internal.size(); ++i)
      want[scene->model.internal[i].name + "_T"] = s.internal_final[i];
    if (bonded(scene->model)) {
      want["beta_T"] = s.internal_final[kBondFraction];
      want["D_T"] = s.internal_final[kBondEnergy];
      want["debond_time"] = s.bonds.debond;
      want["capture_time"] = s.bonds.capture;
      want["escape_time"] = s.bonds.escape;
    }
    for (const auto& [name, value] : want) {
      const auto at = std::find(table.columns.begin(), table.columns.end(), name);
      if (at == table.columns.end()) return "no column " + name;
      const double got = table.rows[p][static_cast<std::size_t>(at - table.columns.begin())];
      // nan is a time that does not exist (no escape): the same in both, whatever its bits
      if (!(std::isnan(got) && std::isnan(value)) && same_bits_of(got) != same_bits_of(value))
        return name + " differs from the library's at point " + std::to_string(p + 1);
    }
  }
  return "";
}

std::string against(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run("run s.toml -q -o run.csv --against exact");
  if (r.code != 0 || !scene) return refused_or(r, "impact run --against exact");
  AnyStepper stepper = make_stepper(*scene);
  RunOutputs outputs;
  outputs.against_exact = true;
  const ErrorNorms e = *run_scene(*scene, stepper, outputs).errors;
  // --quiet leaves the errors, which were asked for.
  for (const double x : {e.sup_u, e.l1_v, e.energy_end})
    if (r.err.find("= " + round_trip(x)) == std::string::npos)
      return "the errors printed differ from the library's: " + r.err;
  if (!scene->model.internal.empty() &&
      r.err.find("sup|z - z_exact| = " + round_trip(e.sup_internal)) == std::string::npos)
    return "no sup|z - z_exact| as the library measures it: " + r.err;
  return "";
}

std::string sidecar_rerun(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run("run s.toml -q -o run.csv");
  if (r.code != 0 || !scene) return refused_or(r, "impact run");
  dir.write("rerun.toml", json_member(slurp(dir / "run.csv.json"), "scene_as_run"));
  const Result again = dir.run("run rerun.toml -q --no-provenance -o rerun.csv");
  if (again.code != 0) return "scene_as_run does not run: " + again.err;
  return slurp(dir / "rerun.csv") == slurp(dir / "run.csv") ? ""
                                                            : "scene_as_run reruns other bytes";
}

std::string plot(const TempDir& dir, const Scene* scene) {
  if (!scene) return refused_or(dir.run("run s.toml -q -o run.csv"), "impact run");
  for (const std::string& args :
       {std::string("run s.toml -q -o run.csv --events ev.csv"),
        std::string("sweep s.toml -q -o sweep.csv --vary time.h=1e-3,5e-4")})
    if (const Result r = dir.run(args); r.code != 0)
      return "could not write what to draw: " + r.err;
  for (const std::string what : {"run.csv --events ev.csv", "ev.csv", "sweep.csv"}) {
    std::filesystem::remove(dir / "p.svg");
    const Result r = dir.run("plot " + what + " -o p.svg");
    if (r.code != 0 || !std::filesystem::exists(dir / "p.svg"))
      return "impact plot " + what + " (exit " + std::to_string(r.code) + "): " + r.err;
  }
  return "";
}

std::string work_precision(const TempDir& dir, const Scene* scene) {
  const Result r = dir.run(
      "work-precision s.toml --methods direct --h 1e-2,5e-3 --repeat 1 -q -o wp.csv "
      "--no-provenance");
  if (r.code != 0 || !scene) return refused_or(r, "impact work-precision");
  const std::string table = slurp(dir / "wp.csv");
  return std::count(table.begin(), table.end(), '\n') == 3 ? "" : "not one row per h: " + table;
}

// The Python module of this build (IMPACT_BUILD_DIR/python), its arrays against the CLI's CSV bit
// for bit (within `tolerance` where they come from another evaluation of the same function);
// "not built" when the module is not in this build (the sanitizer build leaves it out).
std::string python(const TempDir& dir, const Scene* scene, const std::string& call,
                   double tolerance = 0) {
  const std::string module = std::string(IMPACT_BUILD_DIR) + "/python";
  bool built = false;
  if (std::filesystem::exists(module))
    for (const auto& e : std::filesystem::directory_iterator(module))
      built = built || e.path().filename().string().starts_with("impact");
  if (!built) return "not built";
  const std::string script =
      "import csv, sys, numpy as np, impact\n"
      "rows = list(csv.reader(open(sys.argv[1]))) if sys.argv[1] != '-' else [['t']]\n"
      "t = np.array([float(row[0]) for row in rows[1:]])\n"
      "tolerance = float(sys.argv[2])\n"
      "try:\n"
      "    r = impact." +
      call +
      "\n"
      "except impact.SceneError as e:\n"
      "    print('refused:', e); sys.exit(2)\n"
      "for k, name in enumerate(rows[0]):\n"
      "    want = [row[k] for row in rows[1:]]\n"
      "    got = r[name]\n"
      "    if name == 'kind' or name == 'failure':\n"
      "        ok = [str(x) for x in got] == want\n"
      "    else:\n"
      "        w = np.array([float(x) if x != '' else np.nan for x in want])\n"
      "        g = np.asarray(got, dtype=np.float64)\n"
      "        ok = np.array_equal(g.view(np.uint64), w.view(np.uint64)) if tolerance == 0 else "
      "(g.shape == w.shape and np.max(np.abs(g - w), initial=0) <= tolerance)\n"
      "    if not ok: print('column', name, 'differs'); sys.exit(1)\n";
  dir.write("check.py", script);
  const std::string csv = !scene                       ? "-"
                          : call.starts_with("events") ? "ev.csv"
                          : call.starts_with("sweep")  ? "sweep.csv"
                          : call.starts_with("exact")  ? "reference.csv"
                                                       : "run.csv";
  const Result r = dir.shell("PYTHONPATH=" + quote(module) + " /usr/bin/python3 check.py " + csv +
                             " " + round_trip(tolerance));
  if (r.code == 2 && r.out.starts_with("refused"))
    return scene ? "refused a scene the CLI ran" : "refused";
  return r.code == 0 ? "" : "python " + call + ": " + r.out + r.err;
}

const std::vector<Surface> kSurfaces = {
    {"impact run (CSV)", run_csv},
    {"impact run --events", events},
    {"impact sweep", sweep},
    {"impact run --against exact", against},
    {"the sidecar's scene_as_run, rerun", sidecar_rerun},
    {"impact plot", plot},
    {"impact work-precision", work_precision},
    {"impact.run (Python)",
     [](const TempDir& d, const Scene* s) {
       if (s) events(d, s);  // writes run.csv
       return python(d, s, "run('s.toml')");
     }},
    {"impact.events (Python)",
     [](const TempDir& d, const Scene* s) {
       if (s) events(d, s);  // writes ev.csv
       return python(d, s, "events('s.toml')");
     }},
    {"impact.sweep (Python)",
     [](const TempDir& d, const Scene* s) {
       if (s) sweep(d, s);  // writes sweep.csv
       return python(d, s, "sweep('s.toml', vary={'time.h': [1e-3, 5e-4]})");
     }},
    {"impact.exact (Python)",
     [](const TempDir& d, const Scene* s) {
       if (s) {  // the scene's reference as impact run writes it, u, v and z at the grid times
         std::string channels = "[\"u\",\"v\"";
         for (const std::string& z : event_variables(s->model)) channels += ",\"" + z + "\"";
         const Result r =
             d.run("run s.toml -q --no-provenance -o reference.csv --set method.name=" +
                   std::string(reference_for(s->model).name) +
                   " --set 'output.channels=" + channels + "]'");
         if (r.code != 0) return "the reference does not run: " + r.err;
       }
       // exact() is the reference of --against (ReferenceSolution), sampled by its own code: the
       // method exact's rows within rounding (measured: 4.4e-16 in v on the harmonic scene).
       return python(d, s, "exact('s.toml', t)", 1e-12);
     }},
};

// Every cell: the chain is refused everywhere; the bonding field by the surfaces whose methods do
// not follow it yet (work-precision's direct); every other feature is handled everywhere.
Expect expected(const Feature& feature, const Surface& surface) {
  if (feature.name.starts_with("bonding field"))
    if (surface.name.find("work-precision") != std::string::npos) return Expect::refuses;
  return feature.name == "the chain" ? Expect::refuses : Expect::handles;
}

}  // namespace

TEST_CASE(
    "surface matrix: every feature on every surface is handled as the library computes it, "
    "or refused with exit 2",
    "[surfaces][cli][regression]") {
  for (const Feature& feature : kFeatures)
    for (const Surface& surface : kSurfaces) {
      TempDir dir;
      dir.write("s.toml", feature.scene);
      std::optional<Scene> scene;
      if (expected(feature, surface) == Expect::handles) scene = load_scene(dir / "s.toml");
      INFO(feature.name << " on " << surface.name);
      const std::string outcome = surface.check(dir, scene ? &*scene : nullptr);
      if (outcome == "not built") {
        WARN(surface.name << ": the Python module is not in this build; not checked");
        continue;
      }
      CHECK(outcome == (expected(feature, surface) == Expect::handles ? "" : "refused"));
    }
}

TEST_CASE("surface matrix: every subcommand, output option and Python function has a column",
          "[surfaces][cli]") {
  TempDir dir;
  const auto covered = [&](const std::string& name) {
    for (const Surface& s : kSurfaces)
      if (s.name.find(name) != std::string::npos) return true;
    return false;
  };
  // The subcommands `impact --help` lists.
  const Result help = dir.run("--help");
  REQUIRE(help.code == 0);
  const std::size_t list = help.out.find("Subcommands:");
  REQUIRE(list != std::string::npos);
  std::istringstream lines(help.out.substr(list));
  std::string line;
  std::getline(lines, line);
  int subcommands = 0;
  // "  run    Run one scene ...": a name at column 2; a description's next lines are indented more.
  while (std::getline(lines, line) && !line.empty()) {
    if (line.size() < 3 || line[2] == ' ') continue;
    const std::string name = line.substr(2, line.find(' ', 2) - 2);
    ++subcommands;
    INFO("subcommand " << name);
    CHECK(covered("impact " + name));
  }
  CHECK(subcommands >= 4);
  // What `impact run` can write: --out (the CSV), --events, --against's errors, the sidecar.
  const Result run = dir.run("run --help");
  for (const std::string option : {"--events", "--against"}) {
    CHECK(run.out.find(option) != std::string::npos);
    CHECK(covered(option));
  }
  // The Python module's functions.
  const std::string module = std::string(IMPACT_BUILD_DIR) + "/python";
  const Result py =
      dir.shell("PYTHONPATH=" + quote(module) +
                " /usr/bin/python3 -c \"import impact, inspect; print(' '.join(n for n, f in "
                "vars(impact).items() if not n.startswith('_') and callable(f) and not "
                "inspect.isclass(f)))\"");
  if (py.code != 0) {
    WARN("the Python module is not in this build: its functions are not checked");
    return;
  }
  std::istringstream names(py.out);
  for (std::string name; names >> name;) CHECK(covered("impact." + name + " "));
}
