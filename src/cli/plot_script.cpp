// gnuplot_script: a Figure as gnuplot commands, its curves as inline data blocks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "cli/plot_figure.hpp"
#include "impact/output/csv.hpp"

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
  std::string out;
  const auto append = [&](const std::string& part) { out += (out.empty() ? "" : " . ") + part; };
  if (!text.words.empty()) append(literal(text.words));
  if (text.name != Name::none) append("ARG" + std::to_string(static_cast<int>(text.name)));
  if (!text.after.empty()) append(literal(text.after));
  return out.empty() ? literal("") : out;
}

// The figure's geometry in pixels of the png (the pdf and the svg are the same fractions of their
// page): fixed margins around every panel, so that panels of a column share their x extent.
constexpr int kPanelHeight = 260, kLeft = 100, kRight = 24, kTop = 14, kBottom = 48;
constexpr int kTitleLine = 17, kKeyLine = 19;

// A key entry: the series' title and the style of its sample. A vertical mark (vectors) is shown
// as the dotted line it draws.
struct KeyEntry {
  std::string title, with;
};

// The curves first, then the marks drawn over whole panels (a run's events).
std::vector<KeyEntry> key_entries(const Figure& figure) {
  std::vector<KeyEntry> entries;
  for (const bool curves : {true, false})
    for (const Panel& panel : figure.panels)
      for (const Series& s : panel.series) {
        if (s.title.empty() || s.points.empty() || s.autoscale != curves) continue;
        std::string with = s.with;
        if (with.starts_with("vectors nohead")) with = "lines" + with.substr(14);
        // One entry per name: a run's lines and impulses are the same curve's colour.
        const KeyEntry entry{expression(s.title), with};
        if (std::none_of(entries.begin(), entries.end(),
                         [&](const KeyEntry& e) { return e.title == entry.title; }))
          entries.push_back(entry);
      }
  return entries;
}

// The width of an entry's text, in characters: a name given on the command line is counted as 24.
std::size_t title_chars(const Figure& figure) {
  std::size_t chars = 0;
  for (const Panel& panel : figure.panels)
    for (const Series& s : panel.series)
      chars = std::max(chars, s.title.words.size() + s.title.after.size() +
                                  (s.title.name == Name::none ? 0 : 24));
  return chars;
}

struct Layout {
  int width = 0, height = 0, rows = 0, title = 0, key = 0, key_columns = 1;
};

Layout layout(const Figure& figure, std::size_t key_count) {
  Layout l;
  const int panels = static_cast<int>(figure.panels.size());
  l.rows = (panels + figure.columns - 1) / figure.columns;
  l.width = figure.columns == 1 ? 1000 : 1400;
  l.title = 10 + kTitleLine * static_cast<int>(figure.title.size());
  if (key_count > 0) {
    const int entry = static_cast<int>(title_chars(figure) + 8) * 7;  // sample, gap and text
    l.key_columns = std::clamp(l.width * 9 / 10 / entry, 1, static_cast<int>(key_count));
    const int key_rows = (static_cast<int>(key_count) + l.key_columns - 1) / l.key_columns;
    l.key = kKeyLine * key_rows + 8;
  }
  l.height = l.title + l.key + l.rows * kPanelHeight + 8;
  return l;
}

std::string terminal(const std::string& format, const Layout& l) {
  const std::string size = std::to_string(l.width) + "," + std::to_string(l.height);
  if (format == "png") return "pngcairo size " + size + " font ',10'";
  if (format == "svg") return "svg size " + size + " dynamic font ',10'";
  std::ostringstream pdf;  // 100 pixels an inch, font 8 for 10
  pdf << "pdfcairo size " << l.width / 140.0 << "in," << l.height / 130.0 << "in font ',8'";
  return pdf.str();
}

// Margins at screen fractions: x from the left edge, y from the top.
std::string margins(const Layout& l, int left, int right, int top, int bottom) {
  char text[256];
  std::snprintf(text, sizeof text,
                "set lmargin at screen %.5f\nset rmargin at screen %.5f\n"
                "set tmargin at screen %.5f\nset bmargin at screen %.5f\n",
                double(left) / l.width, double(right) / l.width, 1 - double(top) / l.height,
                1 - double(bottom) / l.height);
  return text;
}

std::string panel_margins(const Layout& l, int columns, std::size_t index) {
  const int row = static_cast<int>(index) / columns, column = static_cast<int>(index) % columns;
  const int cell = l.width / columns, above = l.title + l.key + row * kPanelHeight;
  return margins(l, column * cell + kLeft, (column + 1) * cell - kRight, above + kTop,
                 above + kPanelHeight - kBottom);
}

void data_block(std::ostringstream& gp, const std::string& name, const std::vector<Point>& points) {
  gp << name << " << EOD\n";
  for (const Point& p : points) gp << round_trip(p.x) << ' ' << round_trip(p.y) << '\n';
  gp << "EOD\n";
}

struct Extent {
  bool any = false;
  double low = 0, high = 0;
  void add(double x) {
    low = any ? std::min(low, x) : x;
    high = any ? std::max(high, x) : x;
    any = true;
  }
};

// The extents of the points that set the axes (not the marks drawn over the whole panel).
void extents(const Panel& panel, Extent& x, Extent& y) {
  for (const Series& s : panel.series)
    if (s.autoscale)
      for (const Point& p : s.points) {
        x.add(p.x);
        y.add(p.y);
      }
}

// An axis's range from its data: the data's extent with a margin of 4% (of the decades on a log
// axis), or none; constant data is widened by 1% (1 at 0), which gnuplot would do with a warning.
std::string range(const char* axis, const Extent& e, bool log, bool pad) {
  if (!e.any || (log && e.low <= 0)) return std::string("set autoscale ") + axis + "\n";
  double low = e.low, high = e.high;
  if (low == high) {
    const double margin = low == 0 ? 1 : std::abs(low) / 100;
    low = log ? low / 1.1 : low - margin;
    high = log ? high * 1.1 : high + margin;
  } else if (pad && log) {
    const double factor = std::pow(high / low, 0.04);
    low /= factor;
    high *= factor;
  } else if (pad) {
    const double margin = (high - low) * 0.04;
    low -= margin;
    high += margin;
  }
  return std::string("set ") + axis + "range [" + round_trip(low) + ":" + round_trip(high) + "]\n";
}

void plot_panel(std::ostringstream& gp, const Figure& figure, const Extent& shared_x,
                std::size_t index) {
  const Panel& panel = figure.panels[index];
  gp << "set xlabel " << literal(panel.xlabel) << "\nset ylabel " << literal(panel.ylabel) << '\n';
  std::string plots;
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const Series& series = panel.series[s];
    if (series.points.empty()) continue;
    plots += (plots.empty() ? "plot " : ", \\\n     ") +
             ("$d" + std::to_string(index) + "_" + std::to_string(s)) + " using " + series.using_ +
             " with " + series.with + (series.autoscale ? "" : " noautoscale") + " notitle";
  }
  if (plots.empty()) {  // every value of this panel is missing (a sweep's rest_time without rest)
    gp << "unset logscale\nset label 1 'no finite values' at graph 0.5, 0.5 center\n"
       << "plot [0:1] [0:1] NaN notitle\nunset label 1\n";
    return;
  }
  Extent x, y;
  extents(panel, x, y);
  // On a log axis gnuplot's default tics read 0.000010; %g reads 1e-05.
  gp << (panel.log_x ? "set logscale x\nset format x '%g'\n" : "unset logscale x\nset format x\n")
     << (panel.log_y ? "set logscale y\nset format y '%g'\n" : "unset logscale y\nset format y\n")
     << range("x", figure.shared_x ? shared_x : x, panel.log_x, figure.pad_x)
     << range("y", y, panel.log_y, true) << plots << '\n';
}

// The figure's one key: a plot of nothing whose series are the key's entries, drawn in the band
// between the title and the panels.
void plot_key(std::ostringstream& gp, const Layout& l, const std::vector<KeyEntry>& entries) {
  char at[128];
  std::snprintf(at, sizeof at, "set key at screen 0.5, %.5f center top horizontal",
                1 - double(l.title) / l.height);
  gp << margins(l, 10, l.width - 10, l.title, l.title + l.key) << at
     << " Left reverse samplen 3 maxcols " << l.key_columns
     << "\nunset border\nunset tics\nunset xlabel\nunset ylabel\nunset grid\nunset logscale\n";
  gp << "plot [0:1] [0:1] ";
  for (std::size_t i = 0; i < entries.size(); ++i)
    gp << (i ? ", " : "") << "NaN with " << entries[i].with << " title " << entries[i].title;
  gp << '\n';
}

}  // namespace

std::string gnuplot_script(const Figure& figure, const std::string& format) {
  const std::vector<KeyEntry> entries = figure.key ? key_entries(figure) : std::vector<KeyEntry>{};
  const Layout l = layout(figure, entries.size());
  std::ostringstream gp;
  gp << "set terminal " << terminal(format, l) << " noenhanced\nset output\nset grid\nunset key\n";
  for (std::size_t p = 0; p < figure.panels.size(); ++p)
    for (std::size_t s = 0; s < figure.panels[p].series.size(); ++s)
      if (!figure.panels[p].series[s].points.empty())
        data_block(gp, "$d" + std::to_string(p) + "_" + std::to_string(s),
                   figure.panels[p].series[s].points);
  std::string title;
  for (const Text& line : figure.title)
    title += (title.empty() ? "" : " . \"\\n\" . ") + expression(line);
  gp << "set multiplot" << (title.empty() ? "" : " title " + title) << '\n';
  Extent shared_x, unused;
  for (const Panel& panel : figure.panels) extents(panel, shared_x, unused);
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    gp << panel_margins(l, figure.columns, p);
    plot_panel(gp, figure, shared_x, p);
  }
  if (!entries.empty()) plot_key(gp, l, entries);
  gp << "unset multiplot\n";
  return gp.str();
}

}  // namespace impact::cli
