// The scene reader (read_scene.hpp): required tables and keys, the method's keys, the output
// channels and decimation, --set overrides, and the errors of load_scene.
#include "scene_dir_support.hpp"

TEST_CASE("scene: missing required tables and keys", "[scene]") {
  CHECK_SCENE_ERROR(parse(kTime + kDirect),
                    Contains("scene.toml") && Contains("[initial]") && Contains("required table"));
  CHECK_SCENE_ERROR(parse(kInitial + kDirect), Contains("[time]") && Contains("required table"));
  CHECK_SCENE_ERROR(parse(kInitial + kTime), Contains("[method]") && Contains("required table"));
  CHECK_SCENE_ERROR(parse("[initial]\nv0 = -1.0\n" + kTime + kDirect),
                    Contains("scene.toml") && Contains("initial.u0") && Contains("required key"));
  CHECK_SCENE_ERROR(parse("[initial]\nu0 = 5.0\n" + kTime + kDirect),
                    Contains("initial.v0") && Contains("required key"));
  CHECK_SCENE_ERROR(parse(kInitial + kTime + "[method]\n"),
                    Contains("scene.toml") && Contains("method.name") && Contains("required key"));
  CHECK_SCENE_ERROR(parse(""), Contains("scene.toml") && Contains("[initial]"));
}

TEST_CASE("scene: direct and fb_newton read free_flight = closed_form | paper", "[scene]") {
  using impact::FreeFlightForm;
  CHECK(std::get<impact::DirectParams>(parse(kBase).method).free_flight ==
        FreeFlightForm::closed_form);
  CHECK(std::get<impact::DirectParams>(parse(kBase, {"method.free_flight=paper"}).method)
            .free_flight == FreeFlightForm::paper);
  CHECK(std::get<impact::FbNewtonParams>(
            parse(kBase, {"method.name=fb_newton", "method.free_flight=paper"}).method)
            .free_flight == FreeFlightForm::paper);
  CHECK_SCENE_ERROR(
      parse(kBase, {"method.free_flight=stepped"}),
      Contains("method.free_flight = 'stepped'") && Contains("must be one of closed_form, paper"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=exact", "method.free_flight=paper"}),
                    Contains("unknown key for method 'exact'"));
}

TEST_CASE("scene: the method and its keys are checked", "[scene]") {
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"newton\"\n")),
                    Contains("scene.toml") && Contains("method.name = 'newton'") &&
                        Contains("must be one of direct, fb_newton, moreau_jean, penalty, exact"));
  // A key the method does not use (theta is moreau_jean's).
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"direct\"\ntheta = 0.5\n")),
                    Contains("scene.toml") && Contains("method.theta = 0.5") &&
                        Contains("unknown key for method 'direct'") &&
                        Contains("allowed: name, free_flight)"));
  CHECK_SCENE_ERROR(
      parse(with_method("[method]\nname = \"fb_newton\"\nepsilom = 1e-12\n")),
      Contains("method.epsilom") && Contains("allowed: name, epsilon, tolerance, max_iterations"));
  CHECK(impact::method_name(
            parse(with_method("[method]\nname = \"moreau_jean\"\ntheta = 0.5\n")).method) ==
        "moreau_jean");

  // fb_newton ranges.
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nepsilon = 0.0\n")),
                    Contains("scene.toml") && Contains("method.epsilon = 0.0: must be in (0, 1]") &&
                        Contains("must be in (0, 1]"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nepsilon = -1e-15\n")),
                    Contains("method.epsilon = -1e-15") && Contains("must be in (0, 1]"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\ntolerance = 0.0\n")),
                    Contains("method.tolerance = 0.0:") && Contains("must be in (0, 0.1]"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"fb_newton\"\nmax_iterations = 0\n")),
                    Contains("method.max_iterations = 0") && Contains("[1, 10000]"));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"moreau_jean\"\ntheta = 1.5\n")),
                    Contains("method.theta = 1.5") && Contains("must be in [0, 1]"));

  // penalty ranges and stepper names.
  CHECK(impact::method_name(
            parse(with_method("[method]\nname = \"penalty\"\nstiffness = 1e7\n")).method) ==
        "penalty");
  CHECK_SCENE_ERROR(
      parse(with_method("[method]\nname = \"penalty\"\nstiffness = 0.0\n")),
      Contains("scene.toml") && Contains("method.stiffness = 0.0:") && Contains("must be in (0, "));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"penalty\"\nstiffness = -1e6\n")),
                    Contains("method.stiffness = -1e+06") && Contains("must be in (0, "));
  CHECK_SCENE_ERROR(parse(with_method("[method]\nname = \"penalty\"\nstepper = \"euler\"\n")),
                    Contains("scene.toml") && Contains("method.stepper = 'euler'") &&
                        Contains("must be one of") && Contains("rk8pd"));
}

TEST_CASE("scene: output channels and decimation are checked", "[scene]") {
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nchannels = [\"u\", \"iterations\"]\n"),
                    Contains("scene.toml") && Contains("output.channels = 'iterations'") &&
                        Contains("method 'direct'") && Contains("allowed: u, v, N, E, N_scheme)"));
  CHECK_SCENE_ERROR(
      parse(kBase + "[output]\nchannels = [\"u\", \"w\"]\n"),
      Contains("output.channels = 'w'") && Contains("allowed: u, v, N, E, N_scheme)"));
  CHECK_SCENE_ERROR(
      parse(kBase + "[output]\nchannels = [\"u\", \"v\", \"u\"]\n"),
      Contains("scene.toml") && Contains("output.channels = 'u'") && Contains("listed twice"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nchannels = []\n"),
                    Contains("output.channels") && Contains("non-empty"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nevery = 0\n"), Contains("scene.toml") &&
                                                                Contains("output.every = 0") &&
                                                                Contains("integer >= 1"));
  CHECK_SCENE_ERROR(parse(kBase + "[output]\nevery = -5\n"),
                    Contains("output.every = -5") && Contains("integer >= 1"));
  // iterations is fine for a method that counts them.
  impact::Scene s = parse(with_method("[method]\nname = \"fb_newton\"\n") +
                          "[output]\nchannels = [\"iterations\"]\n");
  CHECK(s.output.channels == std::vector<Channel>{Channel::iterations});
  CHECK(s.output.every == 1);
  // [output] with only `every` keeps the default channels.
  s = parse(kBase + "[output]\nevery = 100\n");
  CHECK(s.output.channels == std::vector<Channel>{Channel::u, Channel::v});
  CHECK(s.output.every == 100);
}

TEST_CASE("scene: --set overrides and adds keys before validation", "[scene]") {
  impact::Scene s = parse(kBase, {"time.h=1e-4"});
  CHECK(s.grid.h == 1e-4);
  CHECK(s.grid.steps == 100000);

  s = parse(kBase, {"floor.cor=0.5"});
  CHECK(s.model.cor == 0.5);

  s = parse(kBase, {"method.name=exact"});  // a bare word is read as a string
  CHECK(impact::method_name(s.method) == "exact");
  s = parse(kBase, {"method.name=\"moreau_jean\"", "method.theta=1"});
  CHECK(impact::method_name(s.method) == "moreau_jean");
  s = parse(kBase, {"output.channels=[\"u\", \"E\"]", "output.every=10", "time.T=1"});
  CHECK(s.output.channels == std::vector<Channel>{Channel::u, Channel::E});
  CHECK(s.output.every == 10);
  CHECK(s.grid.steps == 1000);
  s = parse(kBase, {"time.h=0.5", "time.h=0.25"});  // the last one wins
  CHECK(s.grid.h == 0.25);

  // An override is validated like the file, and its errors name it.
  CHECK_SCENE_ERROR(parse(kBase, {"time.h=-1"}),
                    Contains("--set time.h=-1: time.h = -1") && Contains("must be > 0"));
  CHECK_SCENE_ERROR(parse(kBase, {"floor.cor=2"}),
                    Contains("floor.cor = 2") && Contains("must be in [0, 1]"));
  CHECK_SCENE_ERROR(parse(kBase, {"time.hh=0.1"}),
                    Contains("time.hh") && Contains("unknown key") && Contains("T, h"));
  CHECK_SCENE_ERROR(parse(kBase, {"floor.cor=high"}),  // a bare word is a string, not a number
                    Contains("floor.cor = 'high'") && Contains("must be a number"));
  CHECK_SCENE_ERROR(parse(kBase, {"method.name=rk4"}),
                    Contains("method.name = 'rk4'") && Contains("must be one of"));

  // Malformed overrides.
  CHECK_SCENE_ERROR(parse(kBase, {"time.h"}),
                    Contains("--set time.h") && Contains("expected table.key=value"));
  CHECK_SCENE_ERROR(parse(kBase, {"h=0.1"}),
                    Contains("--set h=0.1") && Contains("the key must be table.key"));
  CHECK_SCENE_ERROR(parse(kBase, {".h=0.1"}), Contains("the key must be table.key"));
  CHECK_SCENE_ERROR(parse(kBase, {"time.=0.1"}), Contains("the key must be table.key"));
  CHECK_SCENE_ERROR(parse(kBase, {"a.b.c=1"}), Contains("the key must be table.key"));
  CHECK_SCENE_ERROR(parse(kBase, {"output.channels=[1,"}),
                    Contains("--set output.channels=[1,") && Contains("'[1,' is not a TOML value"));
  CHECK_SCENE_ERROR(parse(kBase, {"time.h="}),
                    Contains("--set time.h=") && Contains("is not a TOML value"));
  CHECK_SCENE_ERROR(parse("x = 1\n" + kBase, {"x.y=1"}),
                    Contains("--set x.y=1") && Contains("[x] is not a table"));
  // An override that adds an unknown table is rejected as in a file.
  CHECK_SCENE_ERROR(parse(kBase, {"flor.cor=0.5"}), Contains("flor") && Contains("unknown table"));
}

TEST_CASE("scene: load_scene names the path of a missing or invalid file", "[scene]") {
  TempDir dir;
  const std::string missing = dir.path + "/no_such_scene.toml";
  CHECK_SCENE_ERROR(impact::load_scene(missing), Contains(missing));

  const std::string broken = dir.write("broken.toml", kBase + "[output\nevery = 1\n");
  CHECK_SCENE_ERROR(impact::load_scene(broken),
                    Contains(broken) && Contains("not a valid TOML scene"));
  CHECK_SCENE_ERROR(parse(kBase + "[output\n"),
                    Contains("scene.toml") && Contains("not a valid TOML scene"));

  // A valid file: errors name its path, and overrides apply.
  const std::string good = dir.write("good.toml", kBase);
  CHECK(impact::load_scene(good).grid.steps == 10000);
  CHECK(impact::load_scene(good, {"time.T=1"}).grid.steps == 1000);
  CHECK_SCENE_ERROR(impact::load_scene(good, {"time.T=0"}),
                    Contains("--set time.T=0: time.T = 0") && Contains("must be > 0"));
}
