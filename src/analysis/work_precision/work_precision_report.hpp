// What experiments/work_precision says about each curve: its observed orders and its errors at
// the reference point (summary.toml; deterministic), and, when its solves were timed, the cost
// of reaching an error (summary.toml and the table of results/work_precision/orders.md).
#pragma once

#include <toml++/toml.h>

#include <string>

#include "analysis/work_precision_curves.hpp"

namespace impact::work_precision {

struct CurveReport {
  toml::table entry;  // the curve's table in summary.toml
  std::string row;    // its row of orders.md
};
CurveReport report_curve(const std::string& scene, const Curve& c, bool timed);

// The head of orders.md's table of curves.
std::string orders_table_head();

}  // namespace impact::work_precision
