// The helpers of the tests of `impact sweep`, test_sweep.cpp and test_sweep_output.cpp.
#pragma once

#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/rest.hpp"
#include "cli_support.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/summary.hpp"
#include "scene/read_scene.hpp"
#include "scene/sweep_grid.hpp"

using Catch::Contains;
using namespace impact;
using namespace impact::testing;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kFigure4 = kSource + "/experiments/figure4/no_cor.toml";
const std::string kFigure4Cor = kSource + "/experiments/figure4/cor075.toml";

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// A CSV row of `impact sweep`: the fields, the failure reason (quoted, may hold commas) last.
inline std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      field += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

inline std::vector<std::vector<std::string>> rows_of(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') rows.push_back(fields(line));
  return rows;
}

inline double number(const std::string& field) {
  char* end = nullptr;
  const double x = std::strtod(field.c_str(), &end);
  REQUIRE((!field.empty() && *end == '\0'));
  return x;
}

// Models and initial states over every branch of the kernels (free flight, impacts, chatter, rest,
// COR 0 and 1, floors away from 0, upward forces), as in test_ensemble.cpp.
inline void random_particles(std::size_t n, std::uint32_t seed, std::vector<Model>& models,
                             std::vector<State>& initial) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    Model m;
    m.phi = i % 3 == 0 ? 0.0 : -3.0 + 6.0 * unit(rng);
    const double forces[] = {0.0, -9.80665, -20.0 * unit(rng), 5.0 * unit(rng)};
    m.f = forces[i % 4];
    const double cors[] = {-1, 0.75, 0.0, 1.0, unit(rng)};
    if (const double c = cors[i / 4 % 5]; c >= 0) m.cor = c;
    models.push_back(m);
    initial.push_back({m.phi + (i % 7 == 0 ? 0.0 : 6.0 * unit(rng)), -5.0 + 10.0 * unit(rng)});
  }
}

inline void check_same(const PointSummary& got, const PointSummary& want) {
  CHECK(same_bits(got.final.u, want.final.u));
  CHECK(same_bits(got.final.v, want.final.v));
  CHECK(same_bits(got.energy_final, want.energy_final));
  CHECK(got.contact_steps == want.contact_steps);
  CHECK(got.impacts == want.impacts);
  CHECK(same_bits(got.first_impact_time, want.first_impact_time));
  CHECK(got.rest_time.has_value() == want.rest_time.has_value());
  CHECK(same_bits(got.rest_time.value_or(-1), want.rest_time.value_or(-1)));
  CHECK(same_bits(got.max_u, want.max_u));
  CHECK(got.iterations == want.iterations);
}

}  // namespace
