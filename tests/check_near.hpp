// CHECK_NEAR: |a - b| <= tol, printing all three with full precision on failure (Catch2 v2 has
// no such matcher for plain doubles with an absolute tolerance).
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>

#define CHECK_NEAR(a, b, tol)                                                                   \
  do {                                                                                          \
    const double a_ = (a), b_ = (b), tol_ = (tol);                                              \
    INFO(std::setprecision(17) << #a " = " << a_ << ", " #b " = " << b_ << ", tol = " << tol_); \
    CHECK(std::fabs(a_ - b_) <= tol_);                                                          \
  } while (0)
