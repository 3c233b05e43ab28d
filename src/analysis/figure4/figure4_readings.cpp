#include "analysis/figure4/figure4_readings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "analysis/fit.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"
#include "impact/steppers/direct.hpp"

namespace impact::figure4 {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The alternative reading of Section 5.2's "alter the velocity at the instant that the particle is
// in contact": solve the step (4-1)-(4-3) as without COR and scale the scheme's own rebound (4-2),
// v^{l+1} = COR v_scheme, on a step with N^l > 0. Ours (restitution.hpp) is v^{l+1} = -COR v^l.
// The closed-form free flight is direct's (direct_step without COR); only the rebound differs, so
// the two rest times compare the readings and nothing else. Not a user-facing method: it exists
// to measure how much C12's rest time owes to the reading.
class ScaledRebound {
 public:
  ScaledRebound(const Model& model, double h)
      : phi_(model.phi), f_(model.f), cor_(newton_e(contact_law(model, kElasticReading))), h_(h) {}

  void initialize(const State& s, std::int64_t) {
    lanes_.anchor_gap = lanes_.gap = s.u - phi_;
    lanes_.anchor_v = lanes_.v = s.v;
    lanes_.since = 0;
  }

  StepInfo do_step(State& s, std::int64_t) {
    // The scheme without COR (no fixed point: -1): v = v_scheme on contact.
    direct_step(lanes_, f_, 0.0, false, std::int64_t{-1}, h_);
    if (lanes_.contact_force > 0) {
      lanes_.v *= cor_;  // the free flight restarts from the scaled rebound
      lanes_.anchor_v = lanes_.v;
    }
    s = {phi_ + lanes_.gap, lanes_.v};
    StepInfo info;
    info.contact_force = lanes_.contact_force;
    return info;
  }

 private:
  double phi_, f_, cor_, h_;
  DirectLanes<double> lanes_;
};

RestAnalysis scaled_rebound_rest(const Scene& scene) {
  ScaledRebound stepper(scene.model, scene.grid.h);
  RestObserver observer(scene.model, scene.grid);
  simulate(stepper, scene.initial, scene.grid, observer);
  return observer.result();
}

Scene as_printed(Scene scene) {
  DirectParams params;
  params.free_flight = FreeFlightForm::paper;
  scene.method = params;
  return scene;
}

// C32: the first contact step (N^l > 0) of direct on the pushed-away scene.
void contact_step(double h, std::size_t c, ContactStepEnergy& row) {
  const Model model{0.0, 9.80665, kContactStepCor[c]};
  const Scene scene = make_scene(model, State{0.01, -1.0}, 0.05, h, DirectParams{});
  const std::vector<Sample> run = record(scene);
  // Row i carries N^{i-1}, the force of the step from t_{i-1} to t_i.
  for (std::size_t i = 1; i < run.size(); ++i)
    if (run[i].N > 0) {
      const Sample& before = run[i - 1];
      const double cor = kContactStepCor[c];
      row.change[c] = run[i].E - before.E;
      row.predicted[c] =
          -(1 - cor * cor) * before.v * before.v / 2 + model.f * (before.u - model.phi);
      row.before[c] = before.E;
      return;
    }
}

}  // namespace

std::vector<double> sorted_rest_times(const std::vector<std::optional<double>>& rest) {
  std::vector<double> r;
  for (const std::optional<double>& t : rest) r.push_back(t.value_or(kInf));
  std::sort(r.begin(), r.end());
  return r;
}

Figure4Readings figure4_readings(const Scene& no_cor, const Scene& cor075,
                                 const std::vector<double>& ensemble_u0) {
  Figure4Readings r;
  const Scene printed = as_printed(no_cor);
  r.paper_rest = analyse_rest(printed).rest_time;
  for (double u0 : ensemble_u0) {
    Scene member = printed;
    member.initial.u = u0;
    r.paper_ensemble.push_back(analyse_rest(member).rest_time);
  }
  r.scaled_rebound = scaled_rebound_rest(cor075);
  for (int k = 0; k <= 12; ++k) {
    ContactStepEnergy row;
    row.h = std::pow(10.0, -(2.0 + k / 4.0));
    for (std::size_t c = 0; c < 2; ++c) contact_step(row.h, c, row);
    r.contact_energy.push_back(row);
  }
  return r;
}

void add_readings_summary(const Figure4Readings& r, toml::table& summary) {
  summary["no_cor"].as_table()->insert(
      "rest_time_direct_paper", r.paper_rest.value_or(std::numeric_limits<double>::quiet_NaN()));
  const std::vector<double> paper = sorted_rest_times(r.paper_ensemble);
  toml::table& ensemble = *summary["ensemble"].as_table();
  ensemble.insert("no_cor_direct_paper_rest_time_min", paper.front());
  ensemble.insert("no_cor_direct_paper_rest_time_median", paper[paper.size() / 2]);
  ensemble.insert("no_cor_direct_paper_rest_time_max", paper.back());
  ensemble.insert(
      "no_cor_direct_paper_at_or_after_7_5",
      static_cast<std::int64_t>(paper.end() - std::lower_bound(paper.begin(), paper.end(), 7.5)));
  ensemble.insert("no_cor_direct_paper_still_bouncing",
                  static_cast<std::int64_t>(std::count(paper.begin(), paper.end(), kInf)));
  toml::table& cor = *summary["cor075"].as_table();
  cor.insert("rest_time_direct_scaled_rebound",
             r.scaled_rebound.rest_time.value_or(std::numeric_limits<double>::quiet_NaN()));
  cor.insert("impacts_direct_scaled_rebound", r.scaled_rebound.impacts);

  toml::table t;
  toml::array h, change[2];
  std::vector<double> hs, rise;
  double max_change[2] = {-kInf, -kInf};
  for (const ContactStepEnergy& row : r.contact_energy) {
    h.push_back(row.h);
    hs.push_back(row.h);
    rise.push_back(row.change[0]);
    for (std::size_t c = 0; c < 2; ++c) {
      change[c].push_back(row.change[c]);
      max_change[c] = std::fmax(max_change[c], row.change[c]);
    }
  }
  const OrderFit fit = fit_order(hs, rise);
  t.insert("h", h);
  t.insert("cor1_change", change[0]);
  t.insert("cor075_change", change[1]);
  t.insert("cor1_change_max", max_change[0]);
  t.insert("cor075_change_max", max_change[1]);
  t.insert("cor1_change_order", fit.order);
  t.insert("cor1_change_order_points", static_cast<std::int64_t>(fit.points));
  summary.insert("contact_energy", t);
}

std::string contact_energy_csv(const Figure4Readings& r) {
  std::ostringstream csv;
  csv << "h,cor1_change,cor1_predicted,cor075_change,cor075_predicted\n";
  for (const ContactStepEnergy& row : r.contact_energy)
    csv << round_trip(row.h) << ',' << round_trip(row.change[0]) << ','
        << round_trip(row.predicted[0]) << ',' << round_trip(row.change[1]) << ','
        << round_trip(row.predicted[1]) << '\n';
  return csv.str();
}

}  // namespace impact::figure4
