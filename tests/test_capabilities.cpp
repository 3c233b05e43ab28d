// Every method against every scene feature it may be given: honoured (exit 0, and the rows differ
// from the same scene without the feature, so a method that ignored it would be caught) or refused
// (exit 2, naming the key refusal() names), as the capability table says; and the table itself,
// row by row, so that a changed capability shows as a changed line here.
#include <catch2/catch.hpp>
#include <string>
#include <variant>
#include <vector>

#include "cli_support.hpp"
#include "impact/methods/capabilities.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;
using namespace impact::testing;

namespace {

// A scene's edits: --unset keys, then --set table.key=value.
struct Edits {
  std::vector<std::string> unset, set;
  std::string cli() const {
    std::string args;
    for (const std::string& u : unset) args += " --unset " + u;
    for (const std::string& s : set) args += " --set '" + s + "'";
    return args;
  }
};

struct Feature {
  std::string name;
  bool impact::Capabilities::*capability;  // nullptr: a feature every method takes
  Edits with, without;                     // what gives the scene the feature, or not
  // The key a refusal names where refusal() does not decide it: a channel is the output's, which
  // the channel table decides (can_write); empty: refusal()'s key.
  std::string channel_key = {};
  std::string scene = "s.toml";  // the scene the feature is given to
};

const std::string kScene =
    "[initial]\nu0 = 0.05\nv0 = -1.0\n[force]\nf = -9.80665\n[time]\nT = 0.2\nh = 1e-3\n"
    "[method]\nname = \"direct\"\n";

const Edits kConstantExpression = {{"force.f"}, {"force.expression=\"-9.80665\""}};

const std::vector<Feature> kFeatures = {
    {"a COR", &impact::Capabilities::restitution, {{}, {"floor.cor=0.5"}}, {}},
    {"a harmonic force", nullptr, {{}, {"force.amplitude=5", "force.omega=30"}}, {}},
    {"a force expression of t",
     &impact::Capabilities::time_expression,
     {{"force.f"}, {"force.expression=\"-9.80665 + 5 * sin(30 * t)\""}},
     kConstantExpression},
    {"a force of the state",
     &impact::Capabilities::state_force,
     {{"force.f"}, {"force.expression=\"-9.80665 - 100 * (u - 0.05) - v\""}},
     kConstantExpression},
    {"a linear force",
     &impact::Capabilities::linear_force,
     {{}, {"force.linear.k=100", "force.linear.u_eq=0.05", "force.linear.c=1"}},
     {}},
    {"the iterations channel",
     &impact::Capabilities::iterations_channel,
     {{}, {"output.channels=[\"u\",\"v\",\"iterations\"]"}},
     {},
     "output.channels"},
    // An internal variable the force reads (a decaying pull, z = e^-t from 1): [[internal]] has no
    // --set, so its scene is another file; the rows are u and v alone, and without the feature the
    // force is what it would be with z held at 0, so a method that ignored z writes the same rows.
    {"internal variables",
     &impact::Capabilities::internal_variables,
     {{"force.f"}, {"force.expression=\"-9.80665 - 5 * z\"", "output.channels=[\"u\",\"v\"]"}},
     kConstantExpression,
     "",
     "si.toml"},
    // A bonding field whose bonds neither break nor saturate (so exact takes it): the rows gain
    // beta and D, and the pull changes u and v.
    {"a bonding field",
     &impact::Capabilities::bonding,
     {{},
      {"bonding.gamma=100", "bonding.L=1e6", "bonding.eps_a=1e6", "bonding.beta0=1",
       "output.channels=[\"u\",\"v\"]"}},
     {}},
};

const std::string kInternal = "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n";

// The feature's scene as a method that takes it reads it (the first one with its capability).
impact::Scene scene_with(const TempDir& dir, const Feature& feature) {
  std::string taker = "direct";
  for (const impact::MethodInfo& m : impact::methods())
    if (feature.capability && m.can.*feature.capability) {
      taker = m.name;
      break;
    }
  std::vector<std::string> set = feature.with.set;
  set.push_back("method.name=" + taker);
  return impact::load_scene(dir / feature.scene, set, feature.with.unset);
}

}  // namespace

TEST_CASE("capabilities: every method takes or refuses every feature, as its table says",
          "[capabilities][regression]") {
  TempDir dir;
  dir.write("s.toml", kScene);
  dir.write("si.toml", kScene + kInternal);
  for (const Feature& feature : kFeatures) {
    const impact::Scene scene = scene_with(dir, feature);
    for (const impact::MethodInfo& method : impact::methods()) {
      const std::string run =
          "run " + feature.scene + " -q --set method.name=" + std::string(method.name);
      INFO(method.name << " with " << feature.name);
      const Result with = dir.run(run + feature.with.cli());
      const auto refused = impact::refusal(method.defaults, scene.model, scene.grid.h);
      if (!feature.capability || method.can.*feature.capability) {
        INFO(with.err);
        CHECK(!refused);
        REQUIRE(with.code == 0);
        const Result without = dir.run(run + feature.without.cli());
        REQUIRE(without.code == 0);
        CHECK(with.out != without.out);
      } else {
        CHECK(with.code == 2);
        CHECK(with.out.empty());
        // The CLI's message names the key refusal() names, as its value: "...: floor.cor = 0.5:".
        const std::string key = feature.channel_key.empty() && refused
                                    ? std::string(refused->table) + "." + std::string(refused->key)
                                    : feature.channel_key;
        CHECK(refused.has_value() == feature.channel_key.empty());
        CHECK_THAT(with.err, Contains(": " + key + " = "));
      }
    }
  }
}

TEST_CASE("capabilities: the table", "[capabilities]") {
  // Restitution, Expression of t, force of the State, Linear force, internal Variables, Adhesion
  // (a bonding field), Iterations channel, reFerence, energy Bound, exact eVents. A harmonic force
  // has no column: every method takes it (kFeatures checks each).
  const std::vector<std::pair<std::string, std::string>> rows = {
      {"direct", "RESLZA--B-"},         {"fb_newton", "RE----I-B-"}, {"moreau_jean", "RESLZA----"},
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
  // exact takes a bonding field in the well with no damage only: the reference is event_driven.
  impact::Model bonded;
  bonded.bonding = impact::Bonding{.gamma = 100.0};
  CHECK(impact::reference_for(bonded).name == "event_driven");
  CHECK(!impact::reference_refusal(bonded));
}

// method_info() and method_of<P>() index the method table by the MethodParams alternative, and the
// [method] keys name their method by that index: the table's rows must be in the variant's order.
TEST_CASE("capabilities: the method table is in the order of MethodParams", "[capabilities]") {
  REQUIRE(impact::methods().size() == std::variant_size_v<impact::MethodParams>);
  for (std::size_t i = 0; i < impact::methods().size(); ++i) {
    INFO(impact::methods()[i].name);
    CHECK(impact::methods()[i].defaults.index() == i);
    CHECK(&impact::method_info(impact::methods()[i].defaults) == &impact::methods()[i]);
  }
  CHECK(impact::method_of<impact::DirectParams>().name == "direct");
  CHECK(impact::method_of<impact::FbNewtonParams>().name == "fb_newton");
  CHECK(impact::method_of<impact::MoreauJeanParams>().name == "moreau_jean");
  CHECK(impact::method_of<impact::PenaltyParams>().name == "penalty");
  CHECK(impact::method_of<impact::ExactParams>().name == "exact");
  CHECK(impact::method_of<impact::EventDrivenParams>().name == "event_driven");
  CHECK(impact::method_of<impact::DirectLocatedParams>().name == "direct_located");
}
