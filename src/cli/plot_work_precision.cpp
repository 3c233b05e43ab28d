// `impact plot` of the table `impact work-precision` writes: read back into the curves the
// command draws with --plot, and drawn by the same figure (work_precision_figure.cpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cli/plot_figure.hpp"
#include "cli/work_precision_command.hpp"
#include "impact/format.hpp"

namespace impact::cli {
namespace {

constexpr const char* kHeader =
    "method,h,steps,sup_u,l1_v,energy_end,first_impact,cpu_s,cpu_median_s,repetitions,batch,"
    "reference_s,reference_parts_at";

double field_number(const CsvLines& lines, const std::string& field, const char* column,
                    bool may_be_empty = false) {
  double x = std::numeric_limits<double>::quiet_NaN();
  if (field.empty() && may_be_empty) return x;
  if (!parse_number(field, x))
    lines.reject(std::string(column) + " = '" + field.substr(0, 40) + "' is not a number");
  return x;
}

}  // namespace

bool is_work_precision_header(const std::string& header) {
  return header == kHeader;
}

Figure read_work_precision_figure(CsvLines& lines, const std::string& header) {
  if (!is_work_precision_header(header))
    lines.reject("not the table of impact work-precision (its header is '" + header.substr(0, 80) +
                 "')");
  const std::size_t columns = split_fields(header).size();
  std::vector<impact::Curve> curves;
  int repeat = 0;
  std::int64_t rows = 0;
  for (std::string line; lines.next(line); ++rows) {
    const std::vector<std::string> f = split_fields(line);
    if (f.size() != columns)
      lines.reject(std::to_string(f.size()) + " fields where the header has " +
                   std::to_string(columns));
    if (!is_identifier(f[0])) lines.reject("method = '" + f[0].substr(0, 40) + "' is not a name");
    WorkPrecisionPoint p;
    p.h = field_number(lines, f[1], "h");
    p.steps = static_cast<std::int64_t>(field_number(lines, f[2], "steps"));
    p.errors.sup_u = field_number(lines, f[3], "sup_u", true);
    p.errors.l1_v = field_number(lines, f[4], "l1_v", true);
    p.errors.energy_end = field_number(lines, f[5], "energy_end", true);
    p.errors.first_impact = field_number(lines, f[6], "first_impact", true);  // NaN: no impact
    p.cost.min = field_number(lines, f[7], "cpu_s");
    p.cost.median = field_number(lines, f[8], "cpu_median_s");
    const double repetitions = field_number(lines, f[9], "repetitions");
    if (!(repetitions >= 1 && repetitions <= 1e6))
      lines.reject("repetitions = '" + f[9] + "' is not a count of repetitions");
    p.cost.repetitions = static_cast<int>(repetitions);
    repeat = std::max(repeat, p.cost.repetitions);
    auto curve = std::find_if(curves.begin(), curves.end(),
                              [&](const impact::Curve& c) { return c.name == f[0]; });
    if (curve == curves.end()) {
      curves.push_back({f[0], true, {}});
      curve = curves.end() - 1;
    }
    curve->points.push_back(p);
  }
  if (rows == 0) lines.reject("no rows after the header");
  return work_precision_figure(curves, "the scene's reference", repeat);
}

}  // namespace impact::cli
