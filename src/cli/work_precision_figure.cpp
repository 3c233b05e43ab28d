// The figure of `impact work-precision`, in the style of experiments/work_precision/plot.gp: its
// colours, point types and axis labels, one row against CPU time and one against h.
#include <cmath>
#include <string>

#include "cli/work_precision_command.hpp"

namespace impact::cli {
namespace {

// Errors below this are rounding (an energy error of 1e-90 where the scheme keeps E exactly): not
// drawn, as the title says.
constexpr double kRounding = 1e-16;

// plot.gp's col(), point() and dash() for the time-steppers.
std::string style(const std::string& method) {
  const std::string colour = method == "direct"           ? "#0072B2"
                             : method == "direct_located" ? "#E41A1C"
                             : method == "fb_newton"      ? "#56B4E9"
                             : method == "moreau_jean"    ? "#009E73"
                                                          : "#7F7F7F";
  const std::string point = method == "direct"           ? "7"
                            : method == "direct_located" ? "3"
                            : method == "fb_newton"      ? "6"
                                                         : "5";
  return "linespoints lw 1.5 ps 0.8 pt " + point + " dt " + (method == "fb_newton" ? "2" : "1") +
         " lc rgb '" + colour + "'";
}

}  // namespace

Figure work_precision_figure(const std::vector<impact::Curve>& curves, const std::string& reference,
                             int repeat) {
  Figure figure;
  figure.title = {Text("work against precision: ", Name::csv),
                  Text("errors against " + reference + "; CPU time of a solve, best of " +
                       std::to_string(repeat) +
                       " (the reference's time excluded); errors below 1e-16 not drawn")};
  figure.columns = 4;
  figure.key = true;
  for (const bool against_cost : {true, false})
    for (const ErrorMeasure m : kErrorMeasures) {
      Panel panel{against_cost ? "CPU time of a solve [s]" : "step h [s]",
                  std::string(measure_info(m).axis_label), true, true};
      for (const impact::Curve& c : curves) {
        Series s;
        s.with = style(c.name);
        s.title = Text(c.name);
        for (const WorkPrecisionPoint& p : c.points)
          if (const double e = error_of(p.errors, m); e >= kRounding && std::isfinite(e))
            s.points.push_back({against_cost ? p.cost.min : p.h, e});
        panel.series.push_back(std::move(s));
      }
      figure.panels.push_back(std::move(panel));
    }
  return figure;
}

}  // namespace impact::cli
