// The panels of a run, of its events and of a sweep (what each shows, in which style).
#include "cli/plot_figure.hpp"

#include <algorithm>
#include <map>
#include <string_view>
#include <utility>

#include "impact/output/csv.hpp"

namespace impact::cli {
namespace {

constexpr const char* kRunColour = "'#0072B2'";
// Okabe-Ito colours: the event kinds (impact, stick, lift, debond, capture, escape) and a sweep's
// curves.
constexpr const char* kKindColours[] = {"'#D55E00'", "'#009E73'", "'#CC79A7'",
                                        "'#000000'", "'#0072B2'", "'#E69F00'"};
static_assert(std::size(kKindColours) == EventsData::kCount);
constexpr const char* kCurveColours[] = {"'#0072B2'", "'#D55E00'", "'#009E73'", "'#CC79A7'",
                                         "'#E69F00'", "'#56B4E9'", "'#000000'", "'#999999'"};
static_assert(std::size(kCurveColours) == kMaxSweepCurves);

struct ChannelStyle {
  const char* ylabel;
  bool impulses;  // N and iterations hold a value per step (or per row), drawn as such
  const char* colour = kRunColour;
};

// N is the floor's impulse of each step over h; N_scheme the scheme's own N^l of (4-3), which
// Newton's law with a COR does not change: another quantity, so another colour (and a note).
const std::map<std::string, ChannelStyle> kChannelStyles = {
    {"u", {"u(t) [m]", false}},    {"v", {"v(t) [m/s]", false}},
    {"N", {"N(t) [m/s^2]", true}}, {"N_scheme", {"N_scheme(t) [m/s^2]", true, "'#D55E00'"}},
    {"E", {"E(t) [J/kg]", false}}, {"iterations", {"iterations per step", true}},
};

const Text kSchemeForceNote{
    "N: the floor's impulse per step over h; N_scheme: the scheme's solve, before a COR's "
    "rebound replaces the velocity"};

const std::map<std::string, std::string> kQuantityLabels = {
    {"u_T", "u at the last grid time [m]"},
    {"v_T", "v at the last grid time [m/s]"},
    {"E_T", "E at the last grid time [J/kg]"},
    {"contact_steps", "contact steps"},
    {"impacts", "impacts"},
    {"first_impact_time", "first impact time [s]"},
    {"rest_time", "rest time [s]"},
    {"max_u", "largest u [m]"},
    {"iterations", "iterations"},
    {"wall_s", "wall time [s]"},
    {"err_u_sup", "sup |u - u_exact| [m]"},
    {"err_v_l1", "h sum |v - v_exact| [m]"},
    {"err_E_T", "|E(T) - E_exact(T)| [J/kg]"},
    {"err_first_impact", "first impact time error [s]"},
    {"reference_s", "wall time of the reference [s]"},
};

// The y label of a run's channel: its style's, else an internal variable's or the channel's name.
ChannelStyle channel_style(const RunData& run, std::size_t c, std::string& label) {
  const std::string& name = run.channels[c];
  if (!run.internal[c])
    if (const auto it = kChannelStyles.find(name); it != kChannelStyles.end()) {
      label = it->second.ylabel;
      return it->second;
    }
  label = name + "(t)" + (run.internal[c] ? " (internal variable)" : "");
  return {nullptr, false, kRunColour};
}

std::string quantity_label(const std::string& name) {
  if (const auto it = kQuantityLabels.find(name); it != kQuantityLabels.end()) return it->second;
  return name.substr(0, name.size() - 2) + " (internal variable) at the last grid time";
}

// The E channel is the energy of a constant force; with f(t) the CSV does not say which it is:
// its provenance sidecar does, and without one both are named.
const Text kConstantEnergy{
    "E = v^2/2 - f u, kinetic plus potential energy per unit mass under the constant force f"};
const Text kTimeEnergy{"E = v^2/2 - f(0) u(0) - W(t), W the work of the force f(t) since t = 0"};
const Text kEnergyNote[] = {
    {"E = v^2/2 - f u, kinetic plus potential energy per unit mass, for a constant force f;"},
    {"with a force f(t): E = v^2/2 - f(0) u(0) - W(t), W the work of f since t = 0"}};

const Text kThinnedNote{
    "each curve of more than 8192 points drawn through the first, lowest, highest and last of "
    "every group of consecutive points"};

Text thinned_note(std::int64_t rows, const Curve& curve) {
  return {std::to_string(rows) + " rows, each curve drawn through the first, lowest, highest and " +
          "last value of every " + std::to_string(curve.per_bucket()) + " rows"};
}

Series series(std::vector<Point> points, std::string with, Text title) {
  Series s;
  s.points = std::move(points);
  s.with = std::move(with);
  s.title = std::move(title);
  return s;
}

// A reference's impulses are drawn as points at their tips: the zeros would hide the run's.
std::vector<Point> nonzero(std::vector<Point> points) {
  std::erase_if(points, [](const Point& p) { return p.y == 0; });
  return points;
}

// One vertical segment over [low, high] at each kept event time.
Series event_marks(const Curve& times, double low, double high, std::size_t kind,
                   std::int64_t count) {
  Series marks;
  for (const Point& p : times.points()) marks.points.push_back({p.x, low});
  marks.using_ = "1:2:(0):(" + round_trip(high - low) + ")";
  marks.with = std::string("vectors nohead lw 1 dt 3 lc rgb ") + kKindColours[kind];
  marks.title = {std::string(EventsData::kKinds[kind]) + " (" + std::to_string(count) + ")"};
  marks.autoscale = false;
  return marks;
}

}  // namespace

// A run's curves are named by its method (from its provenance), else by its file.
Text run_name(const RunData& run, const std::string& before, Name file,
              const std::string& after = {}) {
  return run.method ? Text{before + *run.method + after} : Text{before, file, after};
}

Figure run_figure(const RunData& run, const RunData* against, const EventsData* events) {
  Figure figure;
  figure.key = against || events;
  figure.shared_x = true;
  figure.pad_x = false;  // t from the first row to the last
  figure.title.push_back(run.method ? Text{"", Name::csv, ": a run of " + *run.method}
                                    : Text{"", Name::csv});
  if (run.curves.front().thinned()) figure.title.push_back(thinned_note(run.rows, run.curves[0]));
  if (std::count(run.channels.begin(), run.channels.end(), "E")) {
    if (!run.force_depends_on_t)
      figure.title.insert(figure.title.end(), std::begin(kEnergyNote), std::end(kEnergyNote));
    else
      figure.title.push_back(*run.force_depends_on_t ? kTimeEnergy : kConstantEnergy);
  }
  if (std::count(run.channels.begin(), run.channels.end(), "N_scheme"))
    figure.title.push_back(kSchemeForceNote);
  for (std::size_t c = 0; c < run.channels.size(); ++c) {
    std::string ylabel;
    const ChannelStyle style = channel_style(run, c, ylabel);
    Panel panel{.xlabel = "t [s]", .ylabel = ylabel};
    const Curve& curve = run.curves[c];
    const Curve* reference = nullptr;
    if (against) {
      const auto it =
          std::find(against->channels.begin(), against->channels.end(), run.channels[c]);
      if (it != against->channels.end())
        reference = &against->curves[static_cast<std::size_t>(it - against->channels.begin())];
    }
    double low = curve.low(), high = curve.high();
    if (reference && !reference->empty()) {
      low = std::min(low, reference->low());
      high = std::max(high, reference->high());
    }
    if (events)
      for (std::size_t k = 0; k < EventsData::kCount; ++k)
        if (events->count[k] > 0)
          panel.series.push_back(event_marks(events->before[k], low, high, k, events->count[k]));
    const std::string colour = std::string(" lc rgb ") + style.colour;
    Text name = run_name(run, "", Name::csv);
    if (std::string_view(style.colour) != kRunColour) name.after += " (" + run.channels[c] + ")";
    panel.series.push_back(series(curve.points(),
                                  (style.impulses ? "impulses lw 1.5" : "lines lw 1.5") + colour,
                                  figure.key ? name : Text{}));
    if (reference)
      panel.series.push_back(series(
          style.impulses ? nonzero(reference->points()) : reference->points(),
          style.impulses ? "points pt 6 ps 0.6 lc rgb 'black'" : "lines lw 1.5 dt 2 lc rgb 'black'",
          style.impulses
              ? run_name(*against, "reference: ", Name::against, ", tips of its impulses")
              : run_name(*against, "reference: ", Name::against)));
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

Figure events_figure(const EventsData& events) {
  Figure figure;
  figure.key = true;
  figure.shared_x = true;
  figure.title.push_back({"", Name::csv});
  std::string counts;
  Panel panel{.xlabel = "t [s]", .ylabel = "v [m/s] before and after"};
  for (std::size_t k = 0; k < EventsData::kCount; ++k) {
    const std::string kind = EventsData::kKinds[k];
    // The bonds' kinds (debond, capture, escape) are counted where a run has them.
    if (k < 3 || events.count[k] > 0)
      counts += (k ? ", " : "") + kind + ": " + std::to_string(events.count[k]);
    if (events.count[k] == 0) continue;
    const std::string colour = std::string(" lc rgb ") + kKindColours[k];
    if (kind == "impact") {
      panel.series.push_back(
          series(events.before[k].points(), "points pt 7 ps 0.6" + colour, {kind + ": v_before"}));
      panel.series.push_back(
          series(events.after[k].points(), "points pt 6 ps 0.9" + colour, {kind + ": v_after"}));
    } else if (kind == "debond" || kind == "escape") {  // v, the same before and after
      panel.series.push_back(
          series(events.before[k].points(), "points pt 9 ps 0.8" + colour, {kind + ": v"}));
    } else {  // at rest, or at the top of a flight: v = 0 before and after
      panel.series.push_back(
          series(events.before[k].points(), "points pt 5 ps 0.6" + colour, {kind + " (v = 0)"}));
    }
  }
  figure.title.push_back({counts});
  for (std::size_t k = 0; k < EventsData::kCount; ++k)
    if (events.before[k].thinned()) {
      figure.title.push_back(kThinnedNote);
      break;
    }
  figure.panels.push_back(std::move(panel));
  // One panel per internal variable: its value at each event, by kind.
  for (std::size_t i = 0; i < events.internal.size(); ++i) {
    Panel z{.xlabel = "t [s]", .ylabel = events.internal[i] + " (internal variable) at the event"};
    for (std::size_t k = 0; k < EventsData::kCount; ++k)
      if (events.count[k] > 0)
        z.series.push_back(series(events.internal_curves[i][k].points(),
                                  std::string("points pt 7 ps 0.6 lc rgb ") + kKindColours[k],
                                  {std::string(EventsData::kKinds[k])}));
    figure.panels.push_back(std::move(z));
  }
  return figure;
}

Figure sweep_figure(const SweepData& sweep) {
  Figure figure;
  figure.key = sweep.curve_names.size() > 1;
  figure.shared_x = true;
  figure.columns = sweep.quantities.size() > 3 ? 2 : 1;
  figure.title.push_back({"", Name::csv});
  figure.title.push_back(
      {std::to_string(sweep.points) + " points" +
       (sweep.failed ? ", of which " + std::to_string(sweep.failed) + " failed (no values)"
                     : std::string())});
  bool x_positive = true;
  double x_low = 0, x_high = 0;
  bool any = false, thinned = false;
  for (const auto& curves : sweep.curves)
    for (const Curve& c : curves) {
      if (c.empty()) continue;
      x_low = any ? std::min(x_low, c.x_low()) : c.x_low();
      x_high = any ? std::max(x_high, c.x_high()) : c.x_high();
      any = true;
      thinned = thinned || c.thinned();
    }
  x_positive = any && x_low > 0;
  if (thinned) figure.title.push_back(kThinnedNote);
  if (std::count(sweep.quantities.begin(), sweep.quantities.end(), "E_T"))
    figure.title.insert(figure.title.end(), std::begin(kEnergyNote), std::end(kEnergyNote));
  for (std::size_t q = 0; q < sweep.quantities.size(); ++q) {
    Panel panel{.xlabel = sweep.keys[0],
                .ylabel = sweep.quantities[q] + ": " + quantity_label(sweep.quantities[q])};
    panel.log_x = x_positive && x_high >= 100 * x_low;
    bool y_positive = true;
    double y_low = 0, y_high = 0;
    bool first = true;
    for (std::size_t c = 0; c < sweep.curve_names.size(); ++c) {
      const Curve& curve = sweep.curves[q][c];
      if (curve.empty()) continue;
      y_positive = y_positive && curve.low() > 0;
      y_low = first ? curve.low() : std::min(y_low, curve.low());
      y_high = first ? curve.high() : std::max(y_high, curve.high());
      first = false;
      panel.series.push_back(series(
          curve.points(), std::string("linespoints lw 1.5 pt 7 ps 0.5 lc rgb ") + kCurveColours[c],
          {sweep.curve_names[c]}));
    }
    panel.log_y = !first && y_positive && y_high >= 1000 * y_low;
    figure.panels.push_back(std::move(panel));
  }
  return figure;
}

}  // namespace impact::cli
