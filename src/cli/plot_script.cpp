// gnuplot_script: a Figure as gnuplot commands, its curves as inline data blocks.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cli/plot_figure.hpp"
#include "impact/output.hpp"

namespace impact::cli {
namespace {

// This code's own words in gnuplot's single quotes, where only '' is special. They are plain
// printable ASCII; anything else is a mistake of this code, not of the input.
std::string literal(const std::string& words) {
  std::string out = "'";
  for (char c : words) {
    if (c < 0x20 || c > 0x7e) throw std::logic_error("plot: a figure's words must be ASCII");
    out += c == '\'' ? std::string("''") : std::string(1, c);
  }
  return out + "'";
}

std::string expression(const Text& text) {
  if (text.name == Name::none) return literal(text.words);
  const std::string arg = "ARG" + std::to_string(static_cast<int>(text.name));
  return text.words.empty() ? arg : literal(text.words) + " . " + arg;
}

std::string terminal(const std::string& format, int columns, int rows, bool key, int lines) {
  const int width = columns == 1 ? 1000 : 1400;
  const int height = rows * (key ? 300 : 260) + 30 + 20 * lines;
  if (format == "png")
    return "pngcairo size " + std::to_string(width) + "," + std::to_string(height) + " font ',10'";
  if (format == "svg")
    return "svg size " + std::to_string(width) + "," + std::to_string(height) +
           " dynamic font ',10'";
  std::ostringstream pdf;  // 100 pixels an inch, font 8 for 10
  pdf << "pdfcairo size " << width / 140.0 << "in," << height / 130.0 << "in font ',8'";
  return pdf.str();
}

void data_block(std::ostringstream& gp, const std::string& name, const std::vector<Point>& points) {
  gp << name << " << EOD\n";
  for (const Point& p : points) gp << round_trip(p.x) << ' ' << round_trip(p.y) << '\n';
  gp << "EOD\n";
}

// gnuplot widens the range of an axis over constant data itself, with a warning (a run of one
// row, a flat channel, a sweep of one point); these ranges say the same without one.
std::string ranges(const Panel& panel) {
  bool any = false;
  Point low, high;
  for (const Series& s : panel.series)
    for (const Point& p : s.points) {
      if (!s.autoscale) continue;
      low = any ? Point{std::min(low.x, p.x), std::min(low.y, p.y)} : p;
      high = any ? Point{std::max(high.x, p.x), std::max(high.y, p.y)} : p;
      any = true;
    }
  const auto range = [&](const char* axis, double lo, double hi) {
    if (!any || lo != hi) return std::string("set autoscale ") + axis + "\n";
    const double margin = lo == 0 ? 1 : std::abs(lo) / 100;
    return std::string("set ") + axis + "range [" + round_trip(lo - margin) + ":" +
           round_trip(hi + margin) + "]\n";
  };
  return range("x", low.x, high.x) + range("y", low.y, high.y);
}

void plot_panel(std::ostringstream& gp, const Panel& panel, std::size_t index) {
  gp << "set xlabel " << literal(panel.xlabel) << "\nset ylabel " << literal(panel.ylabel) << '\n';
  std::string plots;
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const Series& series = panel.series[s];
    if (series.points.empty()) continue;
    plots += (plots.empty() ? "plot " : ", \\\n     ") +
             ("$d" + std::to_string(index) + "_" + std::to_string(s)) + " using " + series.using_ +
             " with " + series.with + (series.autoscale ? "" : " noautoscale") +
             (series.title.empty() ? " notitle" : " title " + expression(series.title));
  }
  if (plots.empty()) {  // every value of this panel is missing (a sweep's rest_time without rest)
    gp << "unset logscale\nset label 1 'no finite values' at graph 0.5, 0.5 center\n"
       << "plot [0:1] [0:1] NaN notitle\nunset label 1\n";
    return;
  }
  // On a log axis gnuplot's default tics read 0.000010; %g reads 1e-05.
  gp << (panel.log_x ? "set logscale x\nset format x '%g'\n" : "unset logscale x\nset format x\n")
     << (panel.log_y ? "set logscale y\nset format y '%g'\n" : "unset logscale y\nset format y\n")
     << ranges(panel) << plots << '\n';
}

}  // namespace

std::string gnuplot_script(const Figure& figure, const std::string& format) {
  const int panels = static_cast<int>(figure.panels.size());
  const int rows = (panels + figure.columns - 1) / figure.columns;
  std::ostringstream gp;
  gp << "set terminal "
     << terminal(format, figure.columns, rows, figure.key, static_cast<int>(figure.title.size()))
     << " noenhanced\nset output\nset grid\n"
     << (figure.key ? "set key outside top center horizontal\n" : "unset key\n");
  for (std::size_t p = 0; p < figure.panels.size(); ++p)
    for (std::size_t s = 0; s < figure.panels[p].series.size(); ++s)
      if (!figure.panels[p].series[s].points.empty())
        data_block(gp, "$d" + std::to_string(p) + "_" + std::to_string(s),
                   figure.panels[p].series[s].points);
  std::string title;
  for (const Text& line : figure.title)
    title += (title.empty() ? "" : " . \"\\n\" . ") + expression(line);
  gp << "set multiplot layout " << rows << "," << figure.columns
     << (title.empty() ? "" : " title " + title) << '\n';
  for (std::size_t p = 0; p < figure.panels.size(); ++p) plot_panel(gp, figure.panels[p], p);
  gp << "unset multiplot\n";
  return gp.str();
}

}  // namespace impact::cli
