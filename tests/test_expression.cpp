// The force compiled once (impact/model/expression.hpp): the scene reader parses force.expression
// and each rate once, the solvers' copies share what it found and each copy that evaluates parses
// once more (muparser binds its variables by address), copies evaluate bit for bit as the
// original, on other threads too, and a bad expression keeps its position in the message.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "impact/forces/force.hpp"
#include "impact/forces/internal.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/expression.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

using Catch::Contains;
using namespace impact;

namespace {

const std::string kState = "-9.81 - 40*(u-0.5) - 0.3*v";

std::string scene_text(const std::string& expression, const std::string& method,
                       const std::string& internal = "") {
  return "[initial]\nu0 = 1.0\nv0 = 0.0\n[floor]\ncor = 0.8\n[force]\nexpression = \"" +
         expression + "\"\n" + internal + "[time]\nT = 1.0\nh = 1e-3\n[method]\nname = \"" +
         method + "\"\n";
}

// The parses that `action` makes.
template <class Action>
std::size_t parses_of(const Action& action) {
  const std::size_t before = expression_parses();
  action();
  return expression_parses() - before;
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

}  // namespace

TEST_CASE("expression: reading a scene parses its force once, and each evaluating copy once more",
          "[expression]") {
  for (const std::string& expression : {kState, std::string("-9.80665 + 4 * sin(2 * t)")}) {
    INFO(expression);
    Scene scene;
    CHECK(parses_of([&] { scene = parse_scene(scene_text(expression, "direct"), "s.toml"); }) == 1);
    REQUIRE(scene.model.expression.is_compiled());
    CHECK(scene.model.expression.text() == expression);
    // What the reader found is read again without a parse, by the capabilities and the solvers.
    CHECK(parses_of([&] { (void)state_force(scene.model); }) == 0);
    CHECK(parses_of([&] { (void)refusal(scene.method, scene.model, scene.grid.h); }) == 0);
    const ForceFunction force(scene.model);
    CHECK(parses_of([&] { const ForceFunction copy = force; }) == 0);
    CHECK(parses_of([&] { (void)force.at(0.25, State{0.7, -0.3}); }) == 1);
    CHECK(parses_of([&] { (void)force.at(0.5, State{0.6, -0.2}); }) == 0);
    // A run: its stepper's copies parse once each, not once a step.
    const std::size_t run = parses_of([&] {
      AnyStepper stepper = make_stepper(scene);
      std::visit([&](auto& s) { simulate(s, scene.initial, scene.grid, [](auto&&...) {}); },
                 stepper);
    });
    CHECK(run >= 1);
    CHECK(run <= 3);
  }
}

TEST_CASE("expression: each internal variable's rate is parsed once when the scene is read",
          "[expression]") {
  const std::string internal = "[[internal]]\nname = \"z\"\ninitial = 1.0\nrate = \"-z\"\n";
  Scene scene;
  CHECK(parses_of([&] {
          scene = parse_scene(scene_text("5 - 15 * z", "event_driven", internal), "s.toml");
        }) == 2);  // the force and the rate
  REQUIRE(scene.model.internal.size() == 1);
  CHECK(scene.model.internal[0].rate.is_compiled());
  CHECK(scene.model.expression.reads_state());
  CHECK(parses_of([&] { const InternalRates rates(scene.model); }) == 0);
}

TEST_CASE("expression: copies evaluate bit for bit as the original, each on its own thread",
          "[expression]") {
  const Expression original(kState, std::vector<InternalVariable>{});
  REQUIRE(original.reads_state());
  const double z[1] = {0.0};
  std::vector<double> expected;
  for (int i = 0; i < 100; ++i) expected.push_back(original(0.01 * i, 0.01 * i, -0.02 * i, z));
  std::vector<std::vector<double>> got(4);
  std::vector<std::thread> threads;
  for (auto& values : got)
    threads.emplace_back([&original, &values, &z] {
      const Expression copy = original;  // copied on its thread, parsed there at its first use
      for (int i = 0; i < 100; ++i) values.push_back(copy(0.01 * i, 0.01 * i, -0.02 * i, z));
    });
  for (auto& thread : threads) thread.join();
  for (const auto& values : got)
    for (std::size_t i = 0; i < expected.size(); ++i) CHECK(bits(values[i]) == bits(expected[i]));
}

TEST_CASE("expression: a text is compiled where it is first needed, and a bad one names its column",
          "[expression]") {
  const Expression text = "2 * t";  // as code that builds a model writes it
  CHECK_FALSE(text.is_compiled());
  CHECK_THROWS_AS(text(1.0), std::logic_error);
  Expression compiled;
  CHECK(parses_of([&] { compiled = text.compiled(std::vector<InternalVariable>{}); }) == 1);
  CHECK(compiled(1.5) == 3.0);
  CHECK(parses_of([&] { (void)compiled.compiled(std::vector<InternalVariable>{}); }) ==
        0);  // compiled already: a copy
  CHECK_THROWS_WITH(Expression("2 * x", std::vector<InternalVariable>{}),
                    Contains("uses \"x\" at position 5"));
  CHECK_THROWS_WITH(Expression("sin(t", std::vector<InternalVariable>{}),
                    Contains("does not parse at position 7"));
  CHECK_THROWS_WITH(parse_scene(scene_text("-9.8 + u*", "direct"), "s.toml"),
                    Contains("s.toml: force.expression = '-9.8 + u*': the expression does not "
                             "parse at position 11"));
}
