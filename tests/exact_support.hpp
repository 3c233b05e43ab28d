// The helpers of the exact solution's tests, test_exact.cpp and test_exact_edges.cpp.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "check_near.hpp"
#include "impact/references/exact.hpp"

using impact::energy;
using impact::ExactSolution;
using impact::ExactStepper;
using impact::Model;
using impact::State;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kG = 9.80665;  // standard gravity: f = -kG
constexpr std::int64_t kZenoCount = std::numeric_limits<std::int64_t>::max() / 2;

inline Model model_of(double f, std::optional<double> cor = std::nullopt, double phi = 0.0) {
  Model m;
  m.phi = phi;
  m.f = f;
  m.cor = cor;
  return m;
}

inline double ulp(double x) {
  return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x);
}
inline double before(double t) {
  return std::nextafter(t, -std::numeric_limits<double>::infinity());
}

}  // namespace
