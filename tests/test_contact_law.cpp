// The contact law as a value (contact_law.hpp): each method's law on each kind of floor is the one
// the table documents, and what a method computes follows its law: where the law without COR and
// the law with COR = 1 are the same (the elastic reading), the runs are the same bits; where they
// are not (the paper's scheme, whose law without COR is its own), the runs differ.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "impact/ensemble/ensemble.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/run/any_stepper.hpp"

using namespace impact;

namespace {

Model floor_with(std::optional<double> cor) {
  Model model;
  model.f = -9.80665;
  model.cor = cor;
  return model;
}

// The table of contact_law.hpp, written out: the law each method reads without floor.cor.
ContactLaw documented_without_cor(const std::string& method) {
  if (method == "direct" || method == "fb_newton") return SchemeLaw{};
  if (method == "penalty") return ComplianceLaw{PenaltyParams{}.stiffness};
  return NewtonLaw{1.0};
}

// Every step's (u, v, N^l) bits of a drop from u = 1 at rest under gravity, h = 1e-3, T = 3 s
// (about five impacts).
std::vector<std::uint64_t> drop(const MethodInfo& method, const Model& model) {
  const Grid grid = Grid::covering(3.0, 1e-3);
  AnyStepper stepper = make_stepper(model, grid.h, method.defaults);
  std::vector<std::uint64_t> bits;
  simulate(stepper, State{1.0, 0.0}, grid, [&](std::int64_t, const State& s, const StepInfo& i) {
    for (const double x : {s.u, s.v, i.contact_force})
      bits.push_back(std::bit_cast<std::uint64_t>(x));
  });
  return bits;
}

}  // namespace

TEST_CASE("each method's contact law on each kind of floor is the documented one",
          "[contact][property]") {
  for (const MethodInfo& method : methods()) {
    const std::string name(method.name);
    INFO("method " << name);
    CHECK(contact_law(floor_with(std::nullopt), method.defaults) == documented_without_cor(name));
    for (const double cor : {0.0, 0.5, 1.0}) {
      INFO("floor.cor = " << cor);
      if (!method.can.restitution) {
        // Compliance has no impact for a COR to act on: the law refuses one, as make_stepper does.
        CHECK_THROWS_AS(contact_law(floor_with(cor), method.defaults), std::invalid_argument);
        CHECK_THROWS_AS(make_stepper(floor_with(cor), 1e-3, method.defaults),
                        std::invalid_argument);
        // Built directly, as a library user would: it used to ignore the COR and run elastic.
        CHECK_THROWS_AS(Penalty(floor_with(cor), 1e-3, PenaltyParams{}), std::invalid_argument);
        continue;
      }
      CHECK(contact_law(floor_with(cor), method.defaults) == ContactLaw{NewtonLaw{cor}});
    }
  }
}

TEST_CASE("contact_law reads floor.cor as Newton's law and each reading without it",
          "[contact][property]") {
  CHECK(contact_law(floor_with(std::nullopt), SchemeLaw{}) == ContactLaw{SchemeLaw{}});
  CHECK(contact_law(floor_with(std::nullopt), kElasticReading) == ContactLaw{NewtonLaw{1.0}});
  CHECK(contact_law(floor_with(std::nullopt), ComplianceLaw{4.0}) ==
        ContactLaw{ComplianceLaw{4.0}});
  CHECK(contact_law(floor_with(0.25), SchemeLaw{}) == ContactLaw{NewtonLaw{0.25}});
  CHECK(contact_law(floor_with(0.25), kElasticReading) == ContactLaw{NewtonLaw{0.25}});
  CHECK_THROWS_AS(contact_law(floor_with(0.25), ComplianceLaw{4.0}), std::invalid_argument);
  CHECK(newton_e(NewtonLaw{0.25}) == 0.25);
  CHECK_THROWS_AS(newton_e(SchemeLaw{}), std::logic_error);
  // What the scheme steppers' rule reads: Newton's law acts only where the law is Newton's.
  const RestitutionRule scheme = restitution_rule(SchemeLaw{});
  CHECK((!scheme.has_cor && scheme.fixed_point == -1));
  const RestitutionRule elastic = restitution_rule(NewtonLaw{1.0});
  CHECK((elastic.has_cor && elastic.cor == 1.0 &&
         elastic.fixed_point == restitution_fixed_point(1.0)));
}

TEST_CASE("a drop with COR = 1 and one without COR are the same run exactly where the law says so",
          "[contact][property]") {
  const Model without = floor_with(std::nullopt), elastic = floor_with(1.0);
  for (const MethodInfo& method : methods()) {
    if (!method.can.restitution) continue;
    INFO("method " << method.name);
    const bool same_law =
        contact_law(without, method.defaults) == contact_law(elastic, method.defaults);
    // The scheme's own law keeps some velocity of where the impact falls in its step: not Newton's
    // law with e = 1.
    CHECK(same_law == !(method.name == "direct" || method.name == "fb_newton"));
    const auto a = drop(method, without), b = drop(method, elastic);
    REQUIRE(a.size() == b.size());
    CHECK((a == b) == same_law);
  }
}

TEST_CASE("the ensemble reads the law as its single-particle steppers do", "[contact][property]") {
  const std::vector<Model> models = {floor_with(std::nullopt), floor_with(1.0)};
  const std::vector<State> initial(2, State{1.0, 0.0});
  for (const auto& [method, name] : {std::pair{EnsembleMethod::direct, "direct"},
                                     std::pair{EnsembleMethod::moreau_jean, "moreau_jean"}}) {
    INFO("ensemble " << name);
    Ensemble ensemble(method, models, initial, 1e-3);
    ensemble.advance(3000);
    const bool same_law = contact_law(models[0], find_method(name)->defaults) ==
                          contact_law(models[1], find_method(name)->defaults);
    const bool same_state = std::bit_cast<std::uint64_t>(ensemble.v()[0]) ==
                                std::bit_cast<std::uint64_t>(ensemble.v()[1]) &&
                            std::bit_cast<std::uint64_t>(ensemble.u()[0]) ==
                                std::bit_cast<std::uint64_t>(ensemble.u()[1]);
    CHECK(same_state == same_law);
  }
}
