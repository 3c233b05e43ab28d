// The COR law v -> -COR v without a product of a subnormal where its result is known
// (restitution.hpp): the same bits as the plain product, for the single particle and the ensemble.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string_view>
#include <vector>

#include "impact/ensemble/ensemble.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/restitution.hpp"
#include "impact/steppers/direct.hpp"

using namespace impact;

namespace {

std::int64_t bits(double x) {
  return std::bit_cast<std::int64_t>(x);
}

// The rule as restitution.hpp applies it on a contact step with a COR.
double restituted(double cor, double v) {
  const double scheme = std::numeric_limits<double>::quiet_NaN();  // not taken: N^l > 0
  double after;
  velocity_after_step(true, cor, restitution_fixed_point(cor), true, v, scheme, after);
  return after;
}

// A processor's multiply, kept from being folded or reordered by the compiler.
double product(double cor, double v) {
  volatile double a = -cor, b = v;
  return a * b;
}

const std::vector<double> kCors = {0.0, 0.25, 0.5,      std::nextafter(0.5, 1.0), 0.6, 0.75, 0.8,
                                   0.9, 0.99, 0.999999, std::nextafter(1.0, 0.0), 1.0};

}  // namespace

TEST_CASE("restitution_fixed_point is the largest subnormal that -COR v maps to -v",
          "[restitution]") {
  CHECK(restitution_fixed_point(0.75) == 2);  // |v| = 2^-1073: 0.75 * 2 units rounds to 2
  CHECK(restitution_fixed_point(0.5) == 0);   // 0.5 * 1 unit is a tie, rounded to 0
  CHECK(restitution_fixed_point(0.0) == 0);   // only +-0
  CHECK(restitution_fixed_point(1.0) == (std::int64_t{1} << 52) - 1);  // every subnormal
  CHECK(restitution_fixed_point(-0.5) == -1);                          // +0 maps to +0, not -0
  CHECK(restitution_fixed_point(std::numeric_limits<double>::quiet_NaN()) == -1);
  std::mt19937_64 rng(17);
  std::vector<double> cors = kCors;
  for (int i = 0; i < 200; ++i) cors.push_back(std::uniform_real_distribution<double>(0, 1)(rng));
  for (const double cor : cors) {
    INFO("COR = " << cor);
    const std::int64_t m = restitution_fixed_point(cor);
    REQUIRE(m >= 0);
    const double v = std::bit_cast<double>(m);
    CHECK(bits(product(cor, v)) == bits(-v));
    if (m + 1 < (std::int64_t{1} << 52)) {
      const double next = std::bit_cast<double>(m + 1);
      CHECK(bits(product(cor, next)) != bits(-next));
    }
  }
}

TEST_CASE("the COR law gives the bits of the plain product for every v", "[restitution]") {
  std::mt19937_64 rng(2024);
  std::vector<double> cors = kCors;
  for (int i = 0; i < 40; ++i) cors.push_back(std::uniform_real_distribution<double>(0, 1)(rng));
  for (const double cor : cors) {
    INFO("COR = " << cor);
    const std::int64_t fixed = restitution_fixed_point(cor);
    std::vector<double> vs = {0.0,
                              std::numeric_limits<double>::min(),
                              std::numeric_limits<double>::denorm_min(),
                              std::numeric_limits<double>::max(),
                              std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()};
    for (std::int64_t m = 0; m < 4096; ++m) vs.push_back(std::bit_cast<double>(m));
    for (std::int64_t d = -3; d <= 3; ++d)
      if (fixed + d >= 0) vs.push_back(std::bit_cast<double>(fixed + d));
    std::uniform_int_distribution<std::int64_t> subnormal(1, (std::int64_t{1} << 52) - 1);
    std::uniform_int_distribution<std::int64_t> any_finite(
        0, bits(std::numeric_limits<double>::max()));
    for (int i = 0; i < 2000; ++i) {
      vs.push_back(std::bit_cast<double>(subnormal(rng)));
      vs.push_back(std::bit_cast<double>(any_finite(rng)));
    }
    for (const double magnitude : vs)
      for (const double v : {magnitude, -magnitude}) {
        INFO("v = " << v);
        const double expected = product(cor, v);
        if (std::isnan(expected))
          CHECK(std::isnan(restituted(cor, v)));
        else
          CHECK(bits(restituted(cor, v)) == bits(expected));
      }
  }
}

// Particles that decay through the subnormals onto the fixed point of their COR and rest there,
// and some that start on it: direct and the ensemble on every instruction set, bit for bit
// (tests/test_ensemble.cpp holds the ensemble to direct on general scenes).
TEST_CASE("a particle coming to rest: the ensemble equals direct bit for bit on every lane",
          "[restitution][ensemble]") {
  const double h = 1e-3;
  const std::int64_t steps = 600;
  std::vector<Model> models;
  std::vector<State> initial;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 64; ++i) {
    Model m;
    m.phi = i % 2 ? 0.0 : 2.0 * unit(rng) - 1.0;
    m.f = -9.80665 * (0.5 + unit(rng));
    m.cor = i % 4 == 0 ? 0.75 : unit(rng);
    models.push_back(m);
    // On the floor with a velocity from 1e-300 (about 60 steps above the subnormals for COR 0.75)
    // down to the smallest subnormal.
    const double v =
        i % 3 == 0 ? 1e-300 * unit(rng) : std::bit_cast<double>(std::int64_t(unit(rng) * 0x1p52));
    initial.push_back({m.phi, i % 2 ? v : -v});
  }
  std::vector<std::vector<State>> single(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    Direct direct(models[i], h, DirectParams{});
    simulate(direct, initial[i], Grid{h, steps},
             [&](std::int64_t l, const State& s, const StepInfo&) {
               if (l > 0) single[i].push_back(s);
             });
  }
  for (const std::string_view isa : Ensemble::supported_instruction_sets()) {
    INFO("instruction set " << isa);
    Ensemble ensemble(EnsembleMethod::direct, models, initial, h);
    ensemble.use(isa);
    for (std::int64_t l = 0; l < steps; ++l) {
      ensemble.advance(1);
      for (std::size_t i = 0; i < models.size(); ++i) {
        const State e = ensemble.state(static_cast<Eigen::Index>(i));
        const State& d = single[i][static_cast<std::size_t>(l)];
        if (bits(e.u) != bits(d.u) || bits(e.v) != bits(d.v))
          FAIL("particle " << i << ", step " << l);
      }
    }
  }
}
