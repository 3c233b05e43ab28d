// Scene files: what is accepted, what each absent table means, and that every rejection throws
// SceneError with a message naming the file, the key, the value and what is allowed.
// Required tables, the method and output tables, --set and load_scene's errors are in
// test_scene_method.cpp.
#include "scene_dir_support.hpp"

TEST_CASE("scene: absent tables mean phi = 0, no COR, f = 0, channels u,v every step", "[scene]") {
  impact::Scene s = parse(kBase);
  CHECK(s.initial.u == 5.0);
  CHECK(s.initial.v == -1.0);
  CHECK(s.model.phi == 0.0);
  CHECK_FALSE(s.model.cor.has_value());
  CHECK(s.model.f == 0.0);
  CHECK(s.T == 10.0);
  CHECK(s.grid.h == 0.001);
  CHECK(s.grid.steps == 10000);
  CHECK(impact::method_name(s.method) == "direct");
  CHECK(s.output.channels == std::vector<Channel>{Channel::u, Channel::v});
  CHECK(s.output.every == 1);
}

TEST_CASE("scene: every table given is read", "[scene]") {
  impact::Scene s = parse(
      "[initial]\nu0 = 2.5\nv0 = 0.5\n"
      "[floor]\nphi = 1.0\ncor = 0.75\n"
      "[force]\nf = -9.80665\n" +
      kTime +
      "[method]\nname = \"fb_newton\"\nepsilon = 1e-12\nmax_iterations = 20\n"
      "[output]\nchannels = [\"E\", \"iterations\", \"u\"]\nevery = 10\n");
  CHECK(s.initial.u == 2.5);
  CHECK(s.initial.v == 0.5);
  CHECK(s.model.phi == 1.0);
  REQUIRE(s.model.cor.has_value());
  CHECK(*s.model.cor == 0.75);
  CHECK(s.model.f == -9.80665);
  CHECK(impact::method_name(s.method) == "fb_newton");
  REQUIRE(std::holds_alternative<impact::FbNewtonParams>(s.method));
  CHECK(std::get<impact::FbNewtonParams>(s.method).epsilon == 1e-12);
  CHECK(std::get<impact::FbNewtonParams>(s.method).max_iterations == 20);
  CHECK(s.output.channels == std::vector<Channel>{Channel::E, Channel::iterations, Channel::u});
  CHECK(s.output.every == 10);
}

TEST_CASE("scene: the experiment scenes load", "[scene]") {
  const std::string dir = std::string(IMPACT_SOURCE_DIR) + "/experiments/";
  for (const char* name : {"figure3/no_cor.toml", "figure3/cor075.toml", "figure4/no_cor.toml",
                           "figure4/cor075.toml"}) {
    INFO(name);
    impact::Scene s = impact::load_scene(dir + name);
    CHECK(s.grid.steps == 10000);
    CHECK(impact::method_name(s.method) == "direct");
    CHECK(s.output.channels ==
          std::vector<Channel>{Channel::u, Channel::v, Channel::N, Channel::E});
  }
  impact::Scene s = impact::load_scene(dir + "figure4/cor075.toml");
  CHECK(s.model.f == -9.80665);
  CHECK(s.model.cor == 0.75);
}

TEST_CASE("scene: integers are accepted where numbers are expected", "[scene]") {
  impact::Scene s = parse(
      "[initial]\nu0 = 5\nv0 = -1\n[floor]\nphi = 1\ncor = 1\n[force]\nf = 0\n"
      "[time]\nT = 10\nh = 1\n" +
      kDirect);
  CHECK(s.initial.u == 5.0);
  CHECK(s.initial.v == -1.0);
  CHECK(s.model.phi == 1.0);
  CHECK(s.model.cor == 1.0);
  CHECK(s.T == 10.0);
  CHECK(s.grid.h == 1.0);
  CHECK(s.grid.steps == 10);
  // Integer method keys, too (fb_newton's epsilon is a number).
  CHECK(impact::method_name(
            parse(with_method("[method]\nname = \"fb_newton\"\nepsilon = 1\n")).method) ==
        "fb_newton");
}

TEST_CASE("scene: steps is T/h when it is whole up to rounding, else floor(T/h): never past T",
          "[scene]") {
  auto steps = [](const std::string& T, const std::string& h) {
    return parse(kInitial + "[time]\nT = " + T + "\nh = " + h + "\n" + kDirect).grid.steps;
  };
  CHECK(steps("10.0", "0.001") == 10000);
  CHECK(steps("0.3", "0.1") == 3);  // 0.3/0.1 = 2.9999999999999996 in doubles: whole, not 2
  CHECK(steps("1.0", "1.0") == 1);  // h = T: one step
  // T not a multiple of h: the grid ends at the last grid time before T.
  CHECK(steps("10.0", "0.3") == 33);        // 33.33...: the last row is at t = 9.9
  CHECK(steps("1.0505", "0.001") == 1050);  // 1050.5
  CHECK(steps("1.0", "0.7") == 1);          // last time 0.7
  // A count beyond 5e8: the rounding allowance is 4 eps of T/h, not a fixed 1e-9 relative (which
  // is 0.4 of a step here), so 400000000.4 steps are 400000000 and end 0.4 before T, not past it.
  CHECK(steps("400000000.4", "1.0") == 400000000);
  CHECK(steps("400000000.0", "1.0") == 400000000);
}

TEST_CASE("scene: unknown tables and keys are rejected with the allowed names", "[scene]") {
  CHECK_SCENE_ERROR(parse(kBase + "[flor]\ncor = 0.5\n"),
                    Contains("scene.toml") && Contains("flor") && Contains("unknown table") &&
                        Contains("initial, floor, force, time, method, output"));
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = 10.0\nh = 0.001\nhh = 0.1\n" + kDirect),
                    Contains("scene.toml") && Contains("time.hh") && Contains("0.1") &&
                        Contains("unknown key") && Contains("T, h"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = 5.0\nv0 = -1.0\nu = 1.0\n" + kTime + kDirect),
                    Contains("scene.toml") && Contains("initial.u ") && Contains("u0, v0"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\nphi = 0.0\nCOR = 0.5\n"),
                    Contains("floor.COR") && Contains("0.5") && Contains("phi, cor"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\ng = -9.8\n"),
                    Contains("force.g") && Contains("-9.8") && Contains("allowed in [force]: f"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nchannel = [\"u\"]\n"),
                    Contains("output.channel") && Contains("channels, every"));
  // A table name used as a key (not a table).
  CHECK_SCENE_ERROR(parse("time = 1.0\n" + kInitial + kDirect),
                    Contains("scene.toml") && Contains("time") && Contains("must be a table"));
}

TEST_CASE("scene: values of the wrong type are rejected", "[scene]") {
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = \"10\"\nh = 0.001\n" + kDirect),
                    Contains("scene.toml") && Contains("time.T") && Contains("'10'") &&
                        Contains("must be a number"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = true\nv0 = -1.0\n" + kTime + kDirect),
                    Contains("initial.u0") && Contains("true") && Contains("must be a number"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = [5.0]\nv0 = -1.0\n" + kTime + kDirect),
                    Contains("initial.u0") && Contains("must be a number"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\ncor = \"0.75\"\n"),
                    Contains("floor.cor") && Contains("'0.75'") && Contains("must be a number"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nf = \"gravity\"\n"),
                    Contains("force.f") && Contains("'gravity'") && Contains("must be a number"));
  CHECK_SCENE_ERROR(parse(kInitial + kTime + "[method]\nname = 3\n"),
                    Contains("method.name") && Contains("3") && Contains("must be a string"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nepsilon = \"small\"\n")),
                    Contains("scene.toml") && Contains("method.epsilon") && Contains("'small'") &&
                        Contains("must be a number"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nmax_iterations = 2.5\n")),
                    Contains("method.max_iterations") && Contains("2.5") &&
                        Contains("must be an integer in [1, "));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nevery = 1.5\n"),
                    Contains("output.every") && Contains("1.5") && Contains("integer >= 1"));
  CHECK_SCENE_ERROR(
      parse(kBase + "[output]\nchannels = \"u\"\n"),
      Contains("output.channels = 'u'") && Contains("non-empty array of channel names"));
  CHECK_SCENE_ERROR(
      parse(kBase + "[output]\nchannels = [1]\n"),
      Contains("output.channels") && Contains("1") && Contains("allowed: u, v, N, E"));
}

TEST_CASE("scene: non-finite numbers are rejected", "[scene]") {
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = inf\nh = 0.001\n" + kDirect),
                    Contains("scene.toml") && Contains("time.T = inf") && Contains("finite"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = nan\nv0 = -1.0\n" + kTime + kDirect),
                    Contains("initial.u0 = nan") && Contains("finite"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = 5.0\nv0 = -inf\n" + kTime + kDirect),
                    Contains("initial.v0 = -inf") && Contains("finite"));
  CHECK_SCENE_ERROR(parse(kBase + "[force]\nf = -inf\n"),
                    Contains("force.f = -inf") && Contains("finite"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\ncor = nan\n"),
                    Contains("floor.cor = nan") && Contains("finite"));
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = 10.0\nh = nan\n" + kDirect),
                    Contains("time.h = nan") && Contains("finite"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"moreau_jean\"\ntheta = nan\n")),
                    Contains("method.theta = nan") && Contains("[0, 1]"));
}

TEST_CASE("scene: the time grid must be positive, h <= T, and T/h countable", "[scene]") {
  auto time = [](const std::string& T, const std::string& h) {
    return parse(kInitial + "[time]\nT = " + T + "\nh = " + h + "\n" + kDirect);
  };
  CHECK_SCENE_ERROR(time("10.0", "0.0"),
                    Contains("scene.toml") && Contains("time.h = 0.0: must be > 0"));
  CHECK_SCENE_ERROR(time("10.0", "-0.001"), Contains("time.h = -0.001") && Contains("must be > 0"));
  CHECK_SCENE_ERROR(time("0.0", "0.001"),
                    Contains("scene.toml") && Contains("time.T = 0.0: must be > 0"));
  CHECK_SCENE_ERROR(time("-1", "0.001"), Contains("time.T = -1") && Contains("must be > 0"));
  CHECK_SCENE_ERROR(time("1.0", "2.0"),
                    Contains("scene.toml") && Contains("time.h = 2.0: must be <= time.T = 1.0"));
  // 1e17 steps: l h is no longer exact in doubles.
  CHECK_SCENE_ERROR(time("1e10", "1e-7"), Contains("scene.toml") && Contains("time.h = 1e-07") &&
                                              Contains("too many") && Contains("2^53"));
  // 2^53 steps exactly is the limit, and is accepted (counted, never run here).
  CHECK(time("9007199254740992.0", "1.0").grid.steps == 9007199254740992LL);
  CHECK_SCENE_ERROR(time("18014398509481984.0", "1.0"), Contains("time.h") && Contains("2^53"));
  // Missing keys.
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nh = 0.001\n" + kDirect),
                    Contains("scene.toml") && Contains("time.T") && Contains("required key"));
  CHECK_SCENE_ERROR(parse(kInitial + "[time]\nT = 10.0\n" + kDirect),
                    Contains("time.h") && Contains("required key"));
}

TEST_CASE("scene: initial data, floor and force are range-checked", "[scene]") {
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = -0.5\nv0 = 0.0\n" + kTime + kDirect),
                    Contains("scene.toml") && Contains("initial.u0 = -0.5") &&
                        Contains("must be >= floor.phi = 0 "));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\nphi = 5.5\n"),
                    Contains("initial.u0 = 5.0: must be >= floor.phi = 5.5"));
  // The floor's value is shown as given, not rounded to 6 decimals.
  CHECK_SCENE_ERROR(
      parse("[initial]\nu0 = 1e-8\nv0 = 0.0\n[floor]\nphi = 2.5e-7\n" + kTime + kDirect),
      Contains("initial.u0 = 1e-08") && Contains("floor.phi = 2.5e-07"));
  // u0 = phi (starting on the floor) is allowed.
  CHECK(parse("[initial]\nu0 = 1.0\nv0 = 0.0\n[floor]\nphi = 1.0\n" + kTime + kDirect).initial.u ==
        1.0);

  CHECK_SCENE_ERROR(parse(kBase + "[floor]\ncor = 1.5\n"), Contains("scene.toml") &&
                                                               Contains("floor.cor = 1.5") &&
                                                               Contains("must be in [0, 1]"));
  CHECK_SCENE_ERROR(parse(kBase + "[floor]\ncor = -0.25\n"),
                    Contains("floor.cor = -0.25") && Contains("must be in [0, 1]"));
  CHECK(parse(kBase + "[floor]\ncor = 0.0\n").model.cor == 0.0);
  CHECK(parse(kBase + "[floor]\ncor = 1.0\n").model.cor == 1.0);

  CHECK_SCENE_ERROR(parse(kBase + "[force]\n"),
                    Contains("[force]") && Contains("the table is empty"));
}
