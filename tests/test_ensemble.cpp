// The ensemble (many particles stepped together on vector lanes) against the single-particle
// solvers: every member must be bit-identical to Direct / MoreauJean run on its own through
// simulate(), at every sampled step, whatever vector code this processor selects.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "impact/ensemble/ensemble.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/moreau_jean.hpp"

using namespace impact;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

struct Member {
  Model model;
  State initial;
};

// Random members covering every branch of the kernels: free flight, impacts off and on the grid,
// resting (f < 0 with a COR, the Zeno end), chatter (direct without COR under gravity), a particle
// starting on the floor, upward forces, floors away from 0, COR 0 and 1.
std::vector<Member> random_members(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Member> members(n);
  for (std::size_t i = 0; i < n; ++i) {
    Member& m = members[i];
    m.model.phi = i % 3 == 0 ? 0.0 : -3.0 + 6.0 * unit(rng);
    const double forces[] = {0.0, -9.80665, -20.0 * unit(rng), 5.0 * unit(rng)};
    m.model.f = forces[i % 4];
    const int cor_kind = static_cast<int>(i / 4 % 5);
    if (cor_kind == 1) m.model.cor = 0.75;
    if (cor_kind == 2) m.model.cor = 0.0;
    if (cor_kind == 3) m.model.cor = 1.0;
    if (cor_kind == 4) m.model.cor = unit(rng);
    m.initial.u = m.model.phi + (i % 7 == 0 ? 0.0 : 6.0 * unit(rng));
    m.initial.v = -5.0 + 10.0 * unit(rng);
  }
  return members;
}

template <class Stepper>
std::vector<State> single_particle_samples(Stepper stepper, const State& initial, double h,
                                           std::int64_t steps, std::int64_t every) {
  std::vector<State> samples;
  simulate(stepper, initial, Grid{h, steps}, [&](std::int64_t l, const State& s, const StepInfo&) {
    if (l > 0 && l % every == 0) samples.push_back(s);
  });
  return samples;
}

void check_bit_identical(EnsembleMethod method, double h, std::int64_t steps, std::int64_t every,
                         std::size_t n, double theta = 0.5) {
  const std::vector<Member> members = random_members(n, 20130706u + static_cast<unsigned>(n));
  std::vector<Model> models;
  std::vector<State> initial;
  for (const Member& m : members) {
    models.push_back(m.model);
    initial.push_back(m.initial);
  }
  std::vector<std::vector<State>> expected;
  for (const Member& m : members) {
    if (method == EnsembleMethod::direct)
      expected.push_back(
          single_particle_samples(Direct(m.model, h, {}), m.initial, h, steps, every));
    else
      expected.push_back(single_particle_samples(MoreauJean(m.model, h, MoreauJeanParams{theta}),
                                                 m.initial, h, steps, every));
  }
  // Every vector code this processor can run, not only the one the constructor picks.
  for (const std::string_view isa : Ensemble::supported_instruction_sets()) {
    Ensemble ensemble(method, models, initial, h, theta);
    ensemble.use(isa);
    INFO("instruction set " << isa << ", " << n << " particles");
    std::int64_t mismatches = 0;
    for (std::size_t k = 0; k * every < static_cast<std::size_t>(steps); ++k) {
      ensemble.advance(every);
      for (std::size_t i = 0; i < n; ++i) {
        const State& e = expected[i][k];
        const State got = ensemble.state(static_cast<Eigen::Index>(i));
        if (!same_bits(got.u, e.u) || !same_bits(got.v, e.v)) {
          if (mismatches++ < 5)
            FAIL_CHECK("particle " << i << " at step " << (k + 1) * every << ": u " << got.u
                                   << " vs " << e.u << ", v " << got.v << " vs " << e.v);
        }
      }
    }
    CHECK(mismatches == 0);
    CHECK(ensemble.steps_done() == steps);
  }
}

}  // namespace

TEST_CASE("ensemble: direct lanes are bit-identical to the single-particle solver",
          "[ensemble][direct]") {
  // 203 particles: not a multiple of any block of lanes, so padding is exercised too.
  check_bit_identical(EnsembleMethod::direct, 1e-3, 20000, 250, 203);
  // A grid step of 2^-10: impacts on grid points (f = 0, integer data) hit the floor exactly.
  check_bit_identical(EnsembleMethod::direct, 0x1p-10, 12000, 1000, 37);
}

TEST_CASE("ensemble: moreau_jean lanes are bit-identical to the single-particle solver",
          "[ensemble][moreau_jean]") {
  check_bit_identical(EnsembleMethod::moreau_jean, 1e-3, 20000, 250, 203);
  check_bit_identical(EnsembleMethod::moreau_jean, 1e-3, 5000, 500, 50, 1.0);
}

TEST_CASE("ensemble: exposes every particle's state, force and step count", "[ensemble]") {
  const std::vector<Model> models(3, Model{0.0, -9.80665, 0.75});
  const std::vector<State> initial{{5, -1}, {1, 0}, {0, 0}};
  Ensemble ensemble(EnsembleMethod::direct, models, initial, 1e-3);
  CHECK(ensemble.size() == 3);
  CHECK(ensemble.u().size() == 3);
  CHECK(ensemble.u()[0] == 5.0);
  CHECK(ensemble.contact_force()[0] == 0.0);
  ensemble.advance(0);
  CHECK(ensemble.steps_done() == 0);
  ensemble.advance(1);
  CHECK(ensemble.steps_done() == 1);
  // The third particle rests on the floor: N = -f on every step, as for Direct.
  CHECK(ensemble.contact_force()[2] == Approx(9.80665).epsilon(1e-12));
  const auto supported = Ensemble::supported_instruction_sets();
  REQUIRE(!supported.empty());
  CHECK(ensemble.instruction_set() == supported.front());  // the widest
  CHECK(supported.back() == "baseline");
  CHECK_THROWS_AS(ensemble.use("sse9"), std::invalid_argument);
}

TEST_CASE("ensemble: rejects inconsistent input", "[ensemble]") {
  const std::vector<Model> models(2);
  const std::vector<State> one{{1, 0}}, two{{1, 0}, {2, 0}};
  CHECK_THROWS_AS(Ensemble(EnsembleMethod::direct, models, one, 1e-3), std::invalid_argument);
  CHECK_THROWS_AS(Ensemble(EnsembleMethod::direct, models, two, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(Ensemble(EnsembleMethod::moreau_jean, models, two, 1e-3, 1.5),
                  std::invalid_argument);
  const std::vector<Model> bad_cor{Model{0.0, 0.0, 1.5}, Model{}};
  CHECK_THROWS_AS(Ensemble(EnsembleMethod::direct, bad_cor, two, 1e-3), std::invalid_argument);
}
