// The figures of `impact plot` as plain data (panels of curves), and the gnuplot script that draws
// one. No name a user gave ever enters the script's text: the data are numbers this code formats,
// the words are this code's own, and the file names reach gnuplot only as the arguments ARG1..ARG3
// of `gnuplot -c` (string variables that gnuplot never parses as commands).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cli/plot_data.hpp"

namespace impact::cli {

// The names given on the command line, as gnuplot sees them.
enum class Name { none = 0, csv = 1, against = 2, events = 3 };

// Text in a figure: `words` (plain ASCII, written by this code) followed by a name, if any, and
// `after` (this code's words again).
struct Text {
  Text() = default;
  Text(std::string words, Name name = Name::none, std::string after = {})
      : words(std::move(words)), name(name), after(std::move(after)) {}
  bool empty() const { return words.empty() && name == Name::none && after.empty(); }
  std::string words;
  Name name = Name::none;
  std::string after;
};

struct Series {
  std::vector<Point> points;
  std::string with;            // gnuplot's `with` clause, e.g. "lines lw 1.5 lc rgb '#0072B2'"
  Text title;                  // empty: no entry in the key
  std::string using_ = "1:2";  // the columns; "1:2:(0):(3.5)" for a vertical mark of height 3.5
  bool autoscale = true;       // false: the axes' ranges are those of the other series
};

struct Panel {
  std::string xlabel{}, ylabel{};
  bool log_x = false, log_y = false;
  std::vector<Series> series{};
};

// Every panel has fixed margins, so that the plot areas of a column share their x extent
// whatever the width of the tic labels, and the axis ranges are those of the data.
struct Figure {
  std::vector<Text> title;  // one line each
  std::vector<Panel> panels;
  int columns = 1;
  // One key for the figure, between its title and its panels: each distinct series (title and
  // style) once, whichever panels draw it.
  bool key = false;
  bool shared_x =
      false;          // every panel's x range is that of all the panels' data (t, a sweep's key)
  bool pad_x = true;  // a margin beyond the data on x (false: t from the first row to the last)
};

// The script for a figure in `format` (png, pdf or svg), drawn to gnuplot's standard output.
std::string gnuplot_script(const Figure& figure, const std::string& format);

// A run's panels, one per channel against t; `against` overlays a reference's channels, `events`
// marks each event on every panel.
Figure run_figure(const RunData& run, const RunData* against, const EventsData* events);
// An events CSV alone: v_before and v_after at each event, by kind.
Figure events_figure(const EventsData& events);
// A sweep: one panel per quantity against the first varied key, one curve per value of the others.
Figure sweep_figure(const SweepData& sweep);

// The table of impact work-precision (plot_work_precision.cpp): the figure of its --plot, every
// error measure against CPU time and against h, one curve per method.
bool is_work_precision_header(const std::string& header);
Figure read_work_precision_figure(CsvLines& lines, const std::string& header);

}  // namespace impact::cli
