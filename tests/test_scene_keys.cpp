// How the scene reader names keys and values: floats and quoted keys in messages, the --set or
// --unset a key came from, suggestions for a typo, --unset, and that the reader enforces the key
// tables that `impact run --help` prints.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "impact/format.hpp"
#include "scene/read_scene.hpp"
#include "scene/scene_keys.hpp"
#include "scene/suggest.hpp"
#include "scene/toml_text.hpp"
#include "scene_support.hpp"

using impact::parse_scene;

TEST_CASE("keys: a message shows a float as a float and quotes a key that is not bare", "[keys]") {
  // 1.0 is a float: shown as 1 it hid why an integer key refused it.
  CHECK_SCENE_ERROR(
      parse(with_method("[method]\nname = \"fb_newton\"\nmax_iterations = 1.0\n")),
      Contains("scene.toml: method.max_iterations = 1.0: must be an integer in [1, "));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nevery = 2.0\n"),
                    Contains("output.every = 2.0: must be an integer >= 1"));
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = -0.0\nh = 0.001\n" + kDirect),
                    Contains("time.T = -0.0: must be > 0"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nf = 1e300\ng = [2.0, 1e-300, 1e+20]\n"),
                    Contains("force.g = [2.0, 1e-300, 1e+20]: unknown key"));
  // A key that is not a bare TOML key is quoted, so that a space or an empty key shows.
  CHECK_SCENE_ERROR(parse("[initial]\n\"u0 \" = 5\nv0 = -1.0\n" + kTime + kDirect),
                    Contains("scene.toml: initial.\"u0 \" = 5: unknown key"));
  CHECK_SCENE_ERROR(parse(kBase + "[\"floor \"]\nphi = 0.0\n"),
                    Contains("scene.toml: \"floor \": unknown table"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\n\"\" = 1\n"), Contains("floor.\"\" = 1: unknown key"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\n\"phi\\u001b\" = 1\n"),
                    Contains("floor.\"phi\\u001b\" = 1: unknown key"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\nphi-0 = 1\n"),
                    Contains("floor.phi-0 = 1: unknown key"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\nx = {\"a b\" = 1, c = 2}\n"),
                    Contains("floor.x = {\"a b\" = 1, c = 2}: unknown key"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"moreau_jean\"\n\"theta \" = 0.5\n")),
                    Contains("scene.toml: method.\"theta \" = 0.5: unknown key for method"));
}

// The message names the --set, not the file.
#define CHECK_SET_ERROR(expr, text) \
  CHECK_SCENE_ERROR(expr, Contains(text) && !Contains("scene.toml"))

TEST_CASE("keys: an error in a --set names the --set, not the file", "[keys]") {
  CHECK_SET_ERROR(parse(kBase, {"time.hh=1"}),
                  "--set time.hh=1: time.hh = 1: unknown key (allowed in [time]: T, h)");
  CHECK_SET_ERROR(parse(kBase, {"time.h=-1", "time.h=-2"}),  // the last one
                  "--set time.h=-2: time.h = -2: must be > 0");
  CHECK_SET_ERROR(parse(kBase, {"flor.cor=0.5"}), "--set flor.cor=0.5: flor: unknown table");
  CHECK_SET_ERROR(parse(kBase, {"method.name=fb_newton", "method.epsilon=0"}),
                  "--set method.epsilon=0: method.epsilon = 0: must be in (0, 1]");
  CHECK_SET_ERROR(parse(kBase, {"method.name=newton"}),
                  "--set method.name=newton: method.name = 'newton': ");
  CHECK_SET_ERROR(parse(kBase, {"time.h"}), "--set time.h: expected table.key=value");
  // What the file says is still blamed on the file.
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\ncor = 2\n", {"time.h=0.01"}),
                    Contains("scene.toml: floor.cor = 2: must be in [0, 1]"));
  CHECK_SCENE_ERROR(
      parse(kInitial + "[time]\nT = 10.0\nh = 0.001\nhh = 1\n" + kDirect, {"time.h=0.01"}),
      Contains("scene.toml: time.hh = 1: unknown key"));
  // A COR from the file and a method from --set: both named.
  CHECK_SCENE_ERROR(
      parse(kBase + "[floor]\ncor = 0.75\n", {"method.name=penalty"}),
      Contains("scene.toml: floor.cor = 0.75: method 'penalty' (--set method.name=penalty) has no "
               "restitution law"));
}

TEST_CASE("keys: a mistyped table, key, method or name gets a suggestion", "[keys]") {
  CHECK_SCENE_ERROR(parse(kBase + "[flor]\ncor = 0.5\n"),
                    Contains("unknown table (allowed: initial, floor, force, time, method, "
                             "output, bonding, internal); did you mean floor?"));
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = 10.0\nh = 0.001\nhh = 0.1\n" + kDirect),
                    Contains("time.hh = 0.1: unknown key (allowed in [time]: T, h); did you mean "
                             "time.h?"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = 5.0\nv0 = -1.0\nu = 1.0\n" + kTime + kDirect),
                    Contains("; did you mean initial.u0?"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\nCOR = 0.5\n"), Contains("; did you mean floor.cor?"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nchanels = ['u']\n"),
                    Contains("; did you mean output.channels?"));
  // A key of another table.
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = 10.0\nh = 0.001\nphi = 0.0\n" + kDirect),
                    Contains("time.phi = 0.0: unknown key") && Contains("did you mean floor.phi?"));
  // Nothing close: no suggestion.
  CHECK_SCENE_ERROR(parse(kBase + "[time]\nx = 1\n"), !Contains("did you mean"));
  CHECK_SCENE_ERROR(parse(kBase + "[initial]\nvelocity = 1\n"), !Contains("did you mean"));
  // The same through --set.
  CHECK_SCENE_ERROR(
      parse(kBase, {"time.hh=1"}),
      Contains("--set time.hh=1: time.hh = 1: unknown key") && Contains("did you mean time.h?"));
  CHECK_SCENE_ERROR(parse(kBase, {"tme.h=1"}), Contains("--set tme.h=1: tme: unknown table") &&
                                                   Contains("did you mean time?"));
  CHECK_SCENE_ERROR(parse(kBase, {"tiem.h=1"}), Contains("did you mean time?"));  // a swap
  CHECK(impact::edit_distance("tiem", "time") == 1);
  CHECK(impact::edit_distance("epsilom", "EPSILON") == 1);
  CHECK(impact::edit_distance("", "abc") == 3);
  CHECK(impact::edit_distance("ca", "abc") == 3);  // optimal string alignment: not 2
  // Method keys, and a key of another method.
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nepsilom = 1e-12\n")),
                    Contains("; did you mean method.epsilon?"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=penalty", "method.stifness=1e7"}),
                    Contains("; did you mean method.stiffness?"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"direct\"\ntheta = 0.5\n")),
                    Contains("unknown key for method 'direct' (allowed: name, free_flight); "
                             "theta is a key of moreau_jean"));
  // Names: methods, steppers, free-flight forms, channels.
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=fb-newton"}), Contains("did you mean fb_newton?"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=Direct"}), Contains("did you mean direct?"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=newton"}), Contains("did you mean fb_newton?"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=runge_kutta"}), !Contains("did you mean"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=penalty", "method.stepper=rk8"}),
                    Contains("did you mean rk8pd?"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.free_flight=closed"}),
                    Contains("did you mean closed_form?"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nchannels = ['u', 'e']\n"),
                    Contains("output.channels = 'e'") && Contains("did you mean E?"));
}

// `impact run --help` prints the key tables (test_cli.cpp checks that); here the reader is held
// to them: every range's edges and every listed name, for every key.
TEST_CASE("keys: the reader enforces what the key tables say", "[keys]") {
  const std::string cor_free = kInitial + kTime + kDirect;
  const auto check = [&](const impact::KeySpec& spec) {
    const std::string key = std::string(spec.table) + "." + std::string(spec.key);
    std::vector<std::string> method;
    if (!spec.method().empty()) method.push_back("method.name=" + std::string(spec.method()));
    const auto with = [&](const std::string& value) {
      auto sets = method;
      sets.push_back(key + "=" + value);
      return sets;
    };
    INFO(key << " (" << spec.method() << ")");
    if (spec.type == impact::KeyType::number || spec.type == impact::KeyType::integer) {
      const impact::Range& r = spec.range;
      if (r.text().empty()) return;
      const double below = r.lo_open ? r.lo : r.lo - 1;
      CHECK_SCENE_ERROR(parse(cor_free, with(impact::shortest(below))),
                        Contains(key + " = ") && Contains(r.text()));
      if (r.bounded()) {
        CHECK_SCENE_ERROR(parse(cor_free, with(impact::shortest(2 * r.hi + 1))),
                          Contains(key + " = ") && Contains(r.text()));
        CHECK_NOTHROW(parse(cor_free, with(impact::shortest(r.hi))));
      }
    } else if (spec.type == impact::KeyType::name && key != "method.name") {
      for (auto choice : spec.choices()) {
        auto sets = with(std::string(choice));
        // A choice that reads a key of its own is given it: bonding.form = "fremond" requires
        // bonding.b (test_bonding_fremond.cpp checks the refusal without it).
        if (key == "bonding.form" && choice == "fremond") sets.push_back("bonding.b=1");
        CHECK_NOTHROW(parse(cor_free, sets));
      }
      const auto choices = spec.choices();
      CHECK_SCENE_ERROR(
          parse(cor_free, with("no_such_name")),
          Contains("must be one of " + impact::join({choices.begin(), choices.end()})));
    }
  };
  for (const auto& spec : impact::scene_keys()) check(spec);
  for (const auto& spec : impact::method_keys()) check(spec);
  // Every method, and every channel some method writes.
  for (const auto& m : impact::methods())
    CHECK(impact::method_name(parse(cor_free, {"method.name=" + std::string(m.name)}).method) ==
          m.name);
  for (auto channel : impact::find_scene_key("output", "channels")->choices())
    CHECK_NOTHROW(parse(
        cor_free, {"method.name=fb_newton", "output.channels=['" + std::string(channel) + "']"}));
}

TEST_CASE("keys: --unset removes a key or a table for one run", "[keys]") {
  const auto unset = [](const std::string& text, const std::vector<std::string>& sets,
                        const std::vector<std::string>& unsets) {
    return parse_scene(text, "scene.toml", sets, unsets);
  };
  const std::string cor = kBase + "[floor]\nphi = 1.0\ncor = 0.75\n[force]\nf = -9.8\n";
  // Penalty on a COR scene: the COR has to go.
  impact::Scene s = unset(cor, {"method.name=penalty"}, {"floor.cor"});
  CHECK(impact::method_name(s.method) == "penalty");
  CHECK_FALSE(s.model.cor.has_value());
  CHECK(s.model.phi == 1.0);
  s = unset(cor, {}, {"force", "floor.phi", "floor.cor", "floor.cor"});  // twice is once
  CHECK(s.model.f == 0.0);
  CHECK(s.model.phi == 0.0);
  // A whole table, then a --set into it: unsets come first.
  s = unset(cor, {"floor.phi=0.5"}, {"floor"});
  CHECK(s.model.phi == 0.5);
  CHECK_FALSE(s.model.cor.has_value());

  // What is not there is an error naming it.
  CHECK_SCENE_ERROR(unset(kBase, {}, {"floor.cor"}),
                    Contains("--unset floor.cor: there is no [floor] in scene.toml"));
  CHECK_SCENE_ERROR(unset(kBase, {}, {"time.hh"}),
                    Contains("--unset time.hh: there is no time.hh in scene.toml") &&
                        Contains("did you mean time.h?"));
  CHECK_SCENE_ERROR(unset(kBase, {}, {"tme"}),
                    Contains("--unset tme: there is no [tme] in scene.toml; did you mean time?"));
  // What it removes is still required.
  CHECK_SCENE_ERROR(unset(kBase, {}, {"initial.u0"}),
                    Contains("--unset initial.u0: initial.u0: required key is missing"));
  CHECK_SCENE_ERROR(unset(kBase, {}, {"time"}),
                    Contains("--unset time: [time]: required table is missing"));
  // Malformed, or also given to --set.
  for (const char* bad : {"", ".h", "time.", "a.b.c", "floor.cor=1"})
    CHECK_SCENE_ERROR(unset(cor, {}, {bad}),
                      Contains("--unset " + std::string(bad) + ": expected table.key or table"));
  CHECK_SCENE_ERROR(unset(cor, {"floor.cor=0.5"}, {"floor.cor"}),
                    Contains("--unset floor.cor: --set floor.cor=0.5 sets it too"));
}
