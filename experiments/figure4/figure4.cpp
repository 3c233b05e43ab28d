// Figure 4 (Section 5.2, f = -9.80665): when the particle comes to rest and how much energy it
// loses, at the paper's h = 1e-3 and over a sweep of h, for `direct` and `fb_newton` against the
// exact solution. The h = 1e-3 trajectories themselves are written by `impact run`
// (experiment.mk).
//
// Usage: exp_figure4 SCENE_DIR RESULTS_DIR
//   reads SCENE_DIR/no_cor.toml and SCENE_DIR/cor075.toml, writes RESULTS_DIR/summary.toml,
//   RESULTS_DIR/h_sweep.csv, RESULTS_DIR/ensemble.csv and RESULTS_DIR/labels.gp.
#include <gsl/gsl_fit.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "impact/exact.hpp"
#include "impact/output.hpp"
#include "analysis/rest.hpp"
#include "scene/read_scene.hpp"

namespace {

using namespace impact;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* const kScenes[] = {"no_cor", "cor075"};
const char* const kMethods[] = {"direct", "fb_newton"};

// The sweep: h = 10^-(2 + i/40), i = 0..120, from 1e-2 to 1e-5. Every 10th value,
// h = 10^-(2 + k/4), k = 0..12, goes into summary.toml (and reference.toml).
constexpr int kSweepPerDecade = 40, kSweepPoints = 3 * kSweepPerDecade + 1, kKeepEvery = 10;
// The ensemble: u0 moved by k ulps, |k| <= kEnsembleUlps, at the paper's h.
constexpr int kEnsembleUlps = 200;

void write_file(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  std::fputs(text.c_str(), file.stream());
  file.commit();
}

Scene scene_for(const std::string& dir, const std::string& name, const std::string& method,
                std::vector<std::string> overrides = {}) {
  overrides.push_back("method.name=" + method);
  return load_scene(dir + "/" + name + ".toml", overrides);
}

double first_impact_loss(const RestAnalysis& a) {
  const ContactEpisode& e = a.episodes.front();
  return e.energy_before - e.energy_after;
}

// The numbers of one column at the scene's own h = 1e-3.
toml::table column(const std::string& dir, const std::string& name) {
  toml::table t;
  for (const char* method : kMethods) {
    const RestAnalysis a = analyse_rest(scene_for(dir, name, method));
    const std::string m = method;
    t.insert("rest_time_" + m, a.rest_time.value_or(kNaN));
    t.insert("impacts_" + m, a.impacts);
    t.insert("energy_loss_" + m, a.energy_loss());
    t.insert("energy_mean_" + m, a.energy_mean);
    t.insert("first_impact_loss_" + m, first_impact_loss(a));
  }
  const Scene direct_scene = scene_for(dir, name, "direct");
  const RestAnalysis direct = analyse_rest(direct_scene);
  const ContactEpisode& first = direct.episodes.front();
  t.insert("first_impact_theta", first.linear_fraction);
  t.insert("first_impact_speed", first.speed_before);
  // (4-6) for the first impact: the step removes N^l (u^l - phi) = 2 theta (1 - theta) v^2 +
  // |f| theta h |v| without COR; with COR the velocity -COR v^l replaces (4-2), so the step
  // removes (1 - COR^2) v^2 / 2 + |f| theta h |v| (the kinetic energy lost plus the fall to phi).
  const double v = first.speed_before, g = -direct_scene.model.f, h = direct_scene.grid.h;
  const double kinetic = direct_scene.model.cor
                             ? (1 - *direct_scene.model.cor * *direct_scene.model.cor) * v * v / 2
                             : 2 * first.linear_fraction * (1 - first.linear_fraction) * v * v;
  t.insert("first_impact_loss_predicted", kinetic + g * first.linear_fraction * h * v);
  const ChannelDifference d =
      max_difference(record(direct_scene), record(scene_for(dir, name, "fb_newton")));
  t.insert("max_diff_u", d.u);
  t.insert("max_diff_v", d.v);
  t.insert("max_diff_N", d.N);
  t.insert("max_diff_E", d.E);
  const ExactSolution exact(direct_scene.model, direct_scene.initial);
  t.insert("exact_rest_time", exact.rest_time().value_or(kNaN));
  t.insert("exact_energy_loss", energy(direct_scene.model, direct_scene.initial) -
                                    energy(direct_scene.model, exact.at(direct_scene.T)));
  t.insert("exact_impacts_until_T",
           exact.rest_time() ? -1 : exact.impacts_until(direct_scene.T));  // -1: infinitely many
  return t;
}

struct SweepRow {
  double h = 0;
  RestAnalysis run[2][2];  // [scene][method]
};

std::vector<SweepRow> sweep(const std::string& dir) {
  std::vector<SweepRow> rows;
  for (int i = 0; i < kSweepPoints; ++i) {
    SweepRow row;
    row.h = std::pow(10.0, -(2.0 + static_cast<double>(i) / kSweepPerDecade));
    for (int s = 0; s < 2; ++s)
      for (int m = 0; m < 2; ++m)
        row.run[s][m] = analyse_rest(
            scene_for(dir, kScenes[s], kMethods[m], {"time.h=" + impact::round_trip(row.h)}));
    rows.push_back(row);
  }
  return rows;
}

// Least-squares slope of log|t_rest - t_inf| against log h (GSL), the order of convergence of the
// rest time with COR.
double rest_time_order(const std::vector<SweepRow>& rows, int method, double zeno) {
  std::vector<double> x, y;
  for (const SweepRow& r : rows)
    if (const auto& t = r.run[1][method].rest_time; t && *t != zeno) {
      x.push_back(std::log(r.h));
      y.push_back(std::log(std::fabs(*t - zeno)));
    }
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return c1;
}

std::string sweep_csv(const std::vector<SweepRow>& rows) {
  std::ostringstream csv;
  csv << "h";
  for (const char* s : kScenes)
    for (const char* m : kMethods)
      for (const char* q :
           {"rest_time", "impacts", "energy_loss", "first_impact_loss", "energy_mean"})
        csv << ',' << s << '_' << m << '_' << q;
  csv << '\n';
  for (const SweepRow& r : rows) {
    csv << impact::round_trip(r.h);
    for (const auto& scene : r.run)
      for (const RestAnalysis& a : scene)
        csv << ',' << (a.rest_time ? impact::round_trip(*a.rest_time) : "nan") << ',' << a.impacts
            << ',' << impact::round_trip(a.energy_loss()) << ','
            << impact::round_trip(first_impact_loss(a)) << ',' << impact::round_trip(a.energy_mean);
    csv << '\n';
  }
  return csv.str();
}

toml::table sweep_summary(const std::vector<SweepRow>& rows, double zeno) {
  toml::table t;
  toml::array h;
  for (std::size_t i = 0; i < rows.size(); i += kKeepEvery) h.push_back(rows[i].h);
  t.insert("h", h);
  for (int s = 0; s < 2; ++s)
    for (int m = 0; m < 2; ++m) {
      toml::array rest, loss, first, impacts;
      for (std::size_t i = 0; i < rows.size(); i += kKeepEvery) {
        const RestAnalysis& a = rows[i].run[s][m];
        rest.push_back(a.rest_time.value_or(kNaN));
        loss.push_back(a.energy_loss());
        first.push_back(first_impact_loss(a));
        impacts.push_back(a.impacts);
      }
      const std::string key = std::string(kScenes[s]) + "_" + kMethods[m];
      t.insert(key + "_rest_time", rest);
      t.insert(key + "_energy_loss", loss);
      t.insert(key + "_first_impact_loss", first);
      t.insert(key + "_impacts", impacts);
    }
  // Over the whole sweep: the spread of the no-COR rest time and of the first-impact loss, and
  // the convergence order of the COR rest time.
  for (int m = 0; m < 2; ++m) {
    const std::string key = kMethods[m];
    double rest_min = INFINITY, rest_max = -INFINITY, loss_min = INFINITY;
    for (const SweepRow& r : rows) {
      const RestAnalysis& a = r.run[0][m];
      if (a.rest_time) {
        rest_min = std::fmin(rest_min, *a.rest_time);
        rest_max = std::fmax(rest_max, *a.rest_time);
      }
      loss_min = std::fmin(loss_min, a.energy_loss());
    }
    t.insert("no_cor_" + key + "_rest_time_min", rest_min);
    t.insert("no_cor_" + key + "_rest_time_max", rest_max);
    t.insert("no_cor_" + key + "_energy_loss_min", loss_min);
    t.insert("cor075_" + key + "_rest_time_order", rest_time_order(rows, m, zeno));
  }
  return t;
}

// Rest times at the paper's h with u0 moved by k ulps, |k| <= kEnsembleUlps: how well the rest
// time is determined by the data.
toml::table ensemble(const std::string& dir, std::string& csv_out) {
  std::vector<double> rest[2][2];
  std::ostringstream csv;
  csv << "k,u0,no_cor_direct,no_cor_fb_newton,cor075_direct,cor075_fb_newton\n";
  for (int k = -kEnsembleUlps; k <= kEnsembleUlps; ++k) {
    const double u0 = 5.0 + k * std::ldexp(1.0, -50);  // ulp(5) = 2^-50
    csv << k << ',' << impact::round_trip(u0);
    for (int s = 0; s < 2; ++s)
      for (int m = 0; m < 2; ++m) {
        const auto t = analyse_rest(scene_for(dir, kScenes[s], kMethods[m],
                                              {"initial.u0=" + impact::round_trip(u0)}))
                           .rest_time;
        csv << ',' << (t ? impact::round_trip(*t) : "nan");
        rest[s][m].push_back(t.value_or(INFINITY));
      }
    csv << '\n';
  }
  csv_out = csv.str();
  toml::table t{{"ulps", kEnsembleUlps}, {"members", 2 * kEnsembleUlps + 1}};
  for (int s = 0; s < 2; ++s)
    for (int m = 0; m < 2; ++m) {
      std::vector<double>& r = rest[s][m];
      std::sort(r.begin(), r.end());
      const std::string key = std::string(kScenes[s]) + "_" + kMethods[m];
      t.insert(key + "_rest_time_min", r.front());
      t.insert(key + "_rest_time_median", r[r.size() / 2]);
      t.insert(key + "_rest_time_max", r.back());  // inf: some member still bounces at T
      t.insert(key + "_at_or_after_7_5",
               static_cast<std::int64_t>(r.end() - std::lower_bound(r.begin(), r.end(), 7.5)));
    }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: exp_figure4 SCENE_DIR RESULTS_DIR\n");
    return 2;
  }
  const std::string dir = argv[1], out = argv[2];
  try {
    toml::table summary;
    for (const char* name : kScenes) summary.insert(name, column(dir, name));
    const double zeno = *summary["cor075"]["exact_rest_time"].value<double>();
    const auto rows = sweep(dir);
    summary.insert("h_sweep", sweep_summary(rows, zeno));
    std::string ensemble_csv;
    summary.insert("ensemble", ensemble(dir, ensemble_csv));
    write_file(out + "/h_sweep.csv", sweep_csv(rows));
    write_file(out + "/ensemble.csv", ensemble_csv);

    std::ostringstream toml_text;
    toml_text
        << "# Figure 4 (Section 5.2): measured by exp_figure4; see experiments/figure4/README.md\n"
        << summary << '\n';
    write_file(out + "/summary.toml", toml_text.str());

    // The numbers the plots print in their titles and keys.
    std::ostringstream labels;
    for (const char* scene : kScenes) {
      for (const char* channel : {"u", "v", "N", "E"})
        labels << "diff_" << scene << "_" << channel << " = "
               << impact::round_trip(
                      *summary[scene][std::string("max_diff_") + channel].value<double>())
               << '\n';
      for (const char* method : kMethods)
        labels << "rest_" << scene << "_" << method << " = "
               << impact::round_trip(
                      *summary[scene][std::string("rest_time_") + method].value<double>())
               << '\n';
    }
    labels << "zeno = " << impact::round_trip(zeno) << '\n';
    labels << "energy0 = "
           << impact::round_trip(energy(load_scene(dir + "/no_cor.toml").model,
                                        load_scene(dir + "/no_cor.toml").initial))
           << '\n';
    labels << "order_direct = "
           << impact::round_trip(
                  *summary["h_sweep"]["cor075_direct_rest_time_order"].value<double>())
           << '\n';
    write_file(out + "/labels.gp", labels.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exp_figure4: %s\n", e.what());
    return 1;
  }
  return 0;
}
