#include "analysis/figure4/figure4.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "analysis/fit.hpp"
#include "impact/output/csv.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/scene.hpp"
#include "scene/read_scene.hpp"

namespace impact::figure4 {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// The ensemble: u0 moved by k ulps, |k| <= kEnsembleUlps, at the paper's h.
constexpr int kEnsembleUlps = 200;

Scene with_method(Scene scene, std::string_view method) {
  scene.method = find_method(method)->defaults;
  return scene;
}

Scene with_step(Scene scene, double h) {
  scene.grid = Grid::covering(scene.T, h);
  return scene;
}

// The scene file of each column, run by each method: [scene][method].
using SceneTable = std::array<std::array<Scene, 2>, 2>;

SceneTable scenes(const ExperimentContext& context) {
  SceneTable table;
  for (std::size_t s = 0; s < 2; ++s) {
    const Scene scene =
        load_scene(context.scene_path("figure4", std::string(kFigure4Scenes[s]) + ".toml"));
    for (std::size_t m = 0; m < 2; ++m) table[s][m] = with_method(scene, kFigure4Methods[m]);
  }
  return table;
}

Figure4Column column(const std::array<Scene, 2>& by_method) {
  Figure4Column c{by_method[0], {analyse_rest(by_method[0]), analyse_rest(by_method[1])}, {}};
  c.difference = max_difference(record(by_method[0]), record(by_method[1]));
  return c;
}

std::vector<Figure4SweepRow> sweep(const SceneTable& table, int per_decade) {
  std::vector<Figure4SweepRow> rows;
  for (int i = 0; i <= 3 * per_decade; ++i) {
    Figure4SweepRow row;
    row.h = std::pow(10.0, -(2.0 + static_cast<double>(i) / per_decade));
    for (std::size_t s = 0; s < 2; ++s)
      for (std::size_t m = 0; m < 2; ++m)
        row.run[s][m] = analyse_rest(with_step(table[s][m], row.h));
    rows.push_back(row);
  }
  return rows;
}

void ensemble(const SceneTable& table, Figure4Data& data) {
  const double u0 = table[0][0].initial.u, ulp = std::nextafter(u0, kInf) - u0;
  for (int k = -kEnsembleUlps; k <= kEnsembleUlps; ++k) {
    data.ensemble_u0.push_back(u0 + k * ulp);
    for (std::size_t s = 0; s < 2; ++s)
      for (std::size_t m = 0; m < 2; ++m) {
        Scene scene = table[s][m];
        scene.initial.u = data.ensemble_u0.back();
        data.ensemble_rest[s][m].push_back(analyse_rest(scene).rest_time);
      }
  }
}

// The numbers of one column at the scene's own h = 1e-3.
toml::table column_summary(const Figure4Column& c) {
  toml::table t;
  for (std::size_t m = 0; m < 2; ++m) {
    const RestAnalysis& a = c.rest[m];
    const std::string method(kFigure4Methods[m]);
    t.insert("rest_time_" + method, a.rest_time.value_or(kNaN));
    t.insert("impacts_" + method, a.impacts);
    t.insert("energy_loss_" + method, a.energy_loss());
    t.insert("energy_mean_" + method, a.energy_mean);
    t.insert("first_impact_loss_" + method, first_impact_loss(a));
  }
  const ContactEpisode& first = c.rest[0].episodes.front();
  t.insert("first_impact_theta", first.linear_fraction);
  t.insert("first_impact_speed", first.speed_before);
  // (4-6) for the first impact: the step removes N^l (u^l - phi) = 2 theta (1 - theta) v^2 +
  // |f| theta h |v| without COR; with COR the velocity -COR v^l replaces (4-2), so the step
  // removes (1 - COR^2) v^2 / 2 + |f| theta h |v| (the kinetic energy lost plus the fall to phi).
  const Model& model = c.scene.model;
  const double v = first.speed_before, g = -model.f, h = c.scene.grid.h;
  const double kinetic = model.cor
                             ? (1 - *model.cor * *model.cor) * v * v / 2
                             : 2 * first.linear_fraction * (1 - first.linear_fraction) * v * v;
  t.insert("first_impact_loss_predicted", kinetic + g * first.linear_fraction * h * v);
  t.insert("max_diff_u", c.difference.u);
  t.insert("max_diff_v", c.difference.v);
  t.insert("max_diff_N", c.difference.N);
  t.insert("max_diff_E", c.difference.E);
  const ExactSolution exact(model, c.scene.initial);
  t.insert("exact_rest_time", exact.rest_time().value_or(kNaN));
  t.insert("exact_energy_loss",
           energy(model, c.scene.initial) - energy(model, exact.at(c.scene.T)));
  t.insert("exact_impacts_until_T",
           exact.rest_time() ? -1 : exact.impacts_until(c.scene.T));  // -1: infinitely many
  return t;
}

// The order of convergence of the COR rest time to the Zeno time: the log-log slope of
// |t_rest - t_inf| against h.
double rest_time_order(const std::vector<Figure4SweepRow>& rows, std::size_t method, double zeno) {
  std::vector<double> h, error;
  for (const Figure4SweepRow& r : rows) {
    h.push_back(r.h);
    const std::optional<double>& t = r.run[1][method].rest_time;
    error.push_back(t ? std::fabs(*t - zeno) : 0.0);  // fit_order leaves out error 0
  }
  return fit_order(h, error).order;
}

// Every (per_decade / 4)-th row: the quarter decades.
std::vector<const Figure4SweepRow*> quarter_decades(const Figure4Data& data) {
  std::vector<const Figure4SweepRow*> rows;
  for (std::size_t i = 0; i < data.sweep.size(); i += data.sweep_per_decade / 4)
    rows.push_back(&data.sweep[i]);
  return rows;
}

toml::table sweep_arrays(const Figure4Data& data) {
  const std::vector<const Figure4SweepRow*> rows = quarter_decades(data);
  toml::table t;
  toml::array h;
  for (const Figure4SweepRow* r : rows) h.push_back(r->h);
  t.insert("h", h);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t m = 0; m < 2; ++m) {
      toml::array rest, loss, first, impacts;
      for (const Figure4SweepRow* r : rows) {
        const RestAnalysis& a = r->run[s][m];
        rest.push_back(a.rest_time.value_or(kNaN));
        loss.push_back(a.energy_loss());
        first.push_back(first_impact_loss(a));
        impacts.push_back(a.impacts);
      }
      const std::string key =
          std::string(kFigure4Scenes[s]) + "_" + std::string(kFigure4Methods[m]);
      t.insert(key + "_rest_time", rest);
      t.insert(key + "_energy_loss", loss);
      t.insert(key + "_first_impact_loss", first);
      t.insert(key + "_impacts", impacts);
    }
  return t;
}

// The quarter-decade arrays, and over the whole sweep the spread of the no-COR rest time and
// energy loss and the convergence order of the COR rest time.
toml::table sweep_summary(const Figure4Data& data, double zeno) {
  toml::table t = sweep_arrays(data);
  for (std::size_t m = 0; m < 2; ++m) {
    const std::string method(kFigure4Methods[m]);
    double rest_min = kInf, rest_max = -kInf, loss_min = kInf;
    for (const Figure4SweepRow& r : data.sweep) {
      const RestAnalysis& a = r.run[0][m];
      if (a.rest_time) {
        rest_min = std::fmin(rest_min, *a.rest_time);
        rest_max = std::fmax(rest_max, *a.rest_time);
      }
      loss_min = std::fmin(loss_min, a.energy_loss());
    }
    t.insert("no_cor_" + method + "_rest_time_min", rest_min);
    t.insert("no_cor_" + method + "_rest_time_max", rest_max);
    t.insert("no_cor_" + method + "_energy_loss_min", loss_min);
    t.insert("cor075_" + method + "_rest_time_order", rest_time_order(data.sweep, m, zeno));
  }
  return t;
}

// The spread of the ensemble's rest times (+inf for a member still bouncing at T).
toml::table ensemble_summary(const Figure4Data& data) {
  toml::table t{{"ulps", kEnsembleUlps}, {"members", 2 * kEnsembleUlps + 1}};
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t m = 0; m < 2; ++m) {
      std::vector<double> r;
      for (const std::optional<double>& rest : data.ensemble_rest[s][m])
        r.push_back(rest.value_or(kInf));
      std::sort(r.begin(), r.end());
      const std::string key =
          std::string(kFigure4Scenes[s]) + "_" + std::string(kFigure4Methods[m]);
      t.insert(key + "_rest_time_min", r.front());
      t.insert(key + "_rest_time_median", r[r.size() / 2]);
      t.insert(key + "_rest_time_max", r.back());
      t.insert(key + "_at_or_after_7_5",
               static_cast<std::int64_t>(r.end() - std::lower_bound(r.begin(), r.end(), 7.5)));
    }
  return t;
}

std::string time_or_nan(const std::optional<double>& t) {
  return t ? round_trip(*t) : "nan";
}

std::string sweep_csv(const Figure4Data& data) {
  std::ostringstream csv;
  csv << "h";
  for (std::string_view s : kFigure4Scenes)
    for (std::string_view m : kFigure4Methods)
      for (const char* q :
           {"rest_time", "impacts", "energy_loss", "first_impact_loss", "energy_mean"})
        csv << ',' << s << '_' << m << '_' << q;
  csv << '\n';
  for (const Figure4SweepRow& r : data.sweep) {
    csv << round_trip(r.h);
    for (const auto& scene : r.run)
      for (const RestAnalysis& a : scene)
        csv << ',' << time_or_nan(a.rest_time) << ',' << a.impacts << ','
            << round_trip(a.energy_loss()) << ',' << round_trip(first_impact_loss(a)) << ','
            << round_trip(a.energy_mean);
    csv << '\n';
  }
  return csv.str();
}

std::string ensemble_csv(const Figure4Data& data) {
  std::ostringstream csv;
  csv << "k,u0,no_cor_direct,no_cor_fb_newton,cor075_direct,cor075_fb_newton,"
         "no_cor_direct_paper\n";
  for (std::size_t i = 0; i < data.ensemble_u0.size(); ++i) {
    csv << static_cast<int>(i) - kEnsembleUlps << ',' << round_trip(data.ensemble_u0[i]);
    for (const auto& scene : data.ensemble_rest)
      for (const auto& rest : scene) csv << ',' << time_or_nan(rest[i]);
    csv << ',' << time_or_nan(data.readings.paper_ensemble[i]) << '\n';
  }
  return csv.str();
}

// The numbers the plots print in their titles and keys.
std::string labels_gp(const Figure4Data& data, const toml::table& summary) {
  std::ostringstream labels;
  for (std::size_t s = 0; s < 2; ++s) {
    const std::string scene(kFigure4Scenes[s]);
    for (const char* channel : {"u", "v", "N", "E"})
      labels << "diff_" << scene << "_" << channel << " = "
             << round_trip(*summary[scene][std::string("max_diff_") + channel].value<double>())
             << '\n';
    for (std::size_t m = 0; m < 2; ++m)
      labels << "rest_" << scene << "_" << kFigure4Methods[m] << " = "
             << round_trip(data.column[s].rest[m].rest_time.value_or(kNaN)) << '\n';
  }
  const Scene& no_cor = data.column[0].scene;
  labels << "zeno = " << round_trip(*summary["cor075"]["exact_rest_time"].value<double>()) << '\n'
         << "energy0 = " << round_trip(energy(no_cor.model, no_cor.initial)) << '\n'
         << "order_direct = "
         << round_trip(*summary["h_sweep"]["cor075_direct_rest_time_order"].value<double>()) << '\n'
         << "rest_no_cor_direct_paper = " << time_or_nan(data.readings.paper_rest) << '\n'
         << "rest_cor075_scaled_rebound = " << time_or_nan(data.readings.scaled_rebound.rest_time)
         << '\n'
         << "late_closed_form = "
         << *summary["ensemble"]["no_cor_direct_at_or_after_7_5"].value<std::int64_t>() << '\n'
         << "late_paper = "
         << *summary["ensemble"]["no_cor_direct_paper_at_or_after_7_5"].value<std::int64_t>()
         << '\n'
         << "bouncing_paper = "
         << *summary["ensemble"]["no_cor_direct_paper_still_bouncing"].value<std::int64_t>() << '\n'
         << "contact_order = "
         << round_trip(*summary["contact_energy"]["cor1_change_order"].value<double>()) << '\n';
  return labels.str();
}

}  // namespace

double first_impact_loss(const RestAnalysis& analysis) {
  const ContactEpisode& e = analysis.episodes.front();
  return e.energy_before - e.energy_after;
}

Figure4Data figure4_data(const ExperimentContext& context, const Figure4Options& options) {
  if (options.sweep_per_decade <= 0 || options.sweep_per_decade % 4 != 0)
    throw std::invalid_argument("figure4: sweep_per_decade must be a positive multiple of 4");
  const SceneTable table = scenes(context);
  Figure4Data data;
  for (std::size_t s = 0; s < 2; ++s) data.column[s] = column(table[s]);
  data.sweep_per_decade = options.sweep_per_decade;
  data.sweep = sweep(table, options.sweep_per_decade);
  ensemble(table, data);
  data.readings = figure4_readings(table[0][0], table[1][0], data.ensemble_u0);
  return data;
}

toml::table run_figure4(const ExperimentContext& context, const Figure4Options& options) {
  const Figure4Data data = figure4_data(context, options);
  toml::table summary;
  for (std::size_t s = 0; s < 2; ++s)
    summary.insert(kFigure4Scenes[s], column_summary(data.column[s]));
  const double zeno = *summary["cor075"]["exact_rest_time"].value<double>();
  summary.insert("h_sweep", sweep_summary(data, zeno));
  summary.insert("ensemble", ensemble_summary(data));
  add_readings_summary(data.readings, summary);
  context.write("h_sweep.csv", [&] { return sweep_csv(data); });
  context.write("contact_energy.csv", [&] { return contact_energy_csv(data.readings); });
  context.write("ensemble.csv", [&] { return ensemble_csv(data); });
  context.write("labels.gp", [&] { return labels_gp(data, summary); });
  return summary;
}

const Experiment kFigure4Experiment{
    "figure4", "Figure 4 (Section 5.2)",
    [](const ExperimentContext& context) { return run_figure4(context); }};

}  // namespace impact::figure4
