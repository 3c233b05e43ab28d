// Every method against every scene feature it may be given: honoured (exit 0, and the rows differ
// from the same scene without the feature, so a method that ignored it would be caught) or refused
// (exit 2, naming the key), as the capability table says; and the table itself, row by row, so
// that a changed capability shows as a changed line here.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "impact/capabilities.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

struct Feature {
  std::string name;
  bool impact::Capabilities::*capability;  // nullptr: a feature every method takes
  std::string with, without;     // the --set/--unset that give the scene the feature, or not
  std::string refused_key;       // what a refusal names
  std::string scene = "s.toml";  // the scene the feature is given to
};

const std::string kScene =
    "[initial]\nu0 = 0.05\nv0 = -1.0\n[force]\nf = -9.80665\n[time]\nT = 0.2\nh = 1e-3\n"
    "[method]\nname = \"direct\"\n";

const std::vector<Feature> kFeatures = {
    {"a COR", &impact::Capabilities::restitution, "--set floor.cor=0.5", "", "floor.cor"},
    {"a harmonic force", nullptr, "--set force.amplitude=5 --set force.omega=30", "",
     "force.amplitude"},
    {"a force expression of t", &impact::Capabilities::time_expression,
     "--unset force.f --set 'force.expression=\"-9.80665 + 5 * sin(30 * t)\"'",
     "--unset force.f --set 'force.expression=\"-9.80665\"'", "force.expression"},
    {"a force of the state", &impact::Capabilities::state_force,
     "--unset force.f --set 'force.expression=\"-9.80665 - 100 * (u - 0.05) - v\"'",
     "--unset force.f --set 'force.expression=\"-9.80665\"'", "force.expression"},
    {"a linear force", &impact::Capabilities::linear_force,
     "--set force.linear.k=100 --set force.linear.u_eq=0.05 --set force.linear.c=1", "",
     "force.linear"},
    {"the iterations channel", &impact::Capabilities::iterations_channel,
     "--set 'output.channels=[\"u\",\"v\",\"iterations\"]'", "", "output.channels"},
    // An internal variable the force reads (a decaying pull, z = e^-t from 1): [[internal]] has no
    // --set, so its scene is another file; the rows are u and v alone, and without the feature the
    // force is what it would be with z held at 0, so a method that ignored z writes the same rows.
    {"internal variables", &impact::Capabilities::internal_variables,
     "--unset force.f --set 'force.expression=\"-9.80665 - 5 * z\"' --set "
     "'output.channels=[\"u\",\"v\"]'",
     "--unset force.f --set 'force.expression=\"-9.80665\"'", "method.name", "si.toml"},
    // A bonding field whose bonds neither break nor saturate (so exact takes it): the rows gain
    // beta and D, and the pull changes u and v.
    {"a bonding field", &impact::Capabilities::bonding,
     "--set bonding.gamma=100 --set bonding.L=1e6 --set bonding.eps_a=1e6 --set bonding.beta0=1 "
     "--set 'output.channels=[\"u\",\"v\"]'",
     "", "method.name"},
};

const std::string kInternal = "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n";

}  // namespace

TEST_CASE("capabilities: every method honours or refuses every feature, as its table says",
          "[capabilities][regression]") {
  TempDir dir;
  dir.write("s.toml", kScene);
  dir.write("si.toml", kScene + kInternal);
  for (const impact::MethodInfo& method : impact::methods())
    for (const Feature& feature : kFeatures) {
      const std::string run = "run s.toml -q --set method.name=" + std::string(method.name) + " ";
      INFO(method.name << " with " << feature.name);
      const Result with =
          dir.run("run " + feature.scene + " -q --set method.name=" + std::string(method.name) +
                  " " + feature.with);
      if (!feature.capability || method.can.*feature.capability) {
        INFO(with.err);
        REQUIRE(with.code == 0);
        const Result without = dir.run(run + feature.without);
        REQUIRE(without.code == 0);
        CHECK(with.out != without.out);
      } else {
        CHECK(with.code == 2);
        CHECK_THAT(with.err, Contains(feature.refused_key));
        CHECK(with.out.empty());
      }
    }
}

TEST_CASE("capabilities: the table", "[capabilities]") {
  // Restitution, Expression of t, force of the State, Linear force, internal Variables, Adhesion
  // (a bonding field), Iterations channel, reFerence, energy Bound, exact eVents. A harmonic force
  // has no column: every method takes it (kFeatures checks each).
  const std::vector<std::pair<std::string, std::string>> rows = {
      {"direct", "RESLZ---B-"},         {"fb_newton", "RE----I-B-"}, {"moreau_jean", "RESLZ-----"},
      {"penalty", "-E----I---"},        {"exact", "R--L-A-FBV"},     {"event_driven", "RESLZA-F-V"},
      {"direct_located", "RE--------"},
  };
  const auto row = [](const impact::Capabilities& c) {
    std::string r;
    r += c.restitution ? 'R' : '-';
    r += c.time_expression ? 'E' : '-';
    r += c.state_force ? 'S' : '-';
    r += c.linear_force ? 'L' : '-';
    r += c.internal_variables ? 'Z' : '-';
    r += c.bonding ? 'A' : '-';
    r += c.iterations_channel ? 'I' : '-';
    r += c.reference ? 'F' : '-';
    r += c.energy_bound ? 'B' : '-';
    r += c.exact_events ? 'V' : '-';
    return r;
  };
  REQUIRE(impact::methods().size() == rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    CHECK(impact::methods()[i].name == rows[i].first);
    CHECK(row(impact::methods()[i].can) == rows[i].second);
  }
  CHECK(impact::reference_for(impact::Model{}).name == "exact");
  impact::Model expression;
  expression.expression = "-9.80665";
  CHECK(impact::reference_for(expression).name == "event_driven");
  impact::Model state;
  state.expression = "-9.80665 - 100 * u - v";
  CHECK(impact::reference_for(state).name == "event_driven");
  impact::Model internal;
  internal.internal = {{"z", 1.0, "-z"}};
  CHECK(impact::reference_for(internal).name == "event_driven");
  impact::Model linear;
  linear.linear = impact::LinearSpring{1.0, 0.1, 0.0};
  CHECK(impact::reference_for(linear).name == "exact");
}
