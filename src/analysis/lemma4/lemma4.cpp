#include "analysis/lemma4/lemma4.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>

#include "analysis/lemma4/weak_solution.hpp"
#include "analysis/order_table.hpp"
#include "analysis/path_distance.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/output/csv.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"

namespace impact::lemma4 {

const Experiment kLemma4Experiment{
    "lemma4",
    "Lemma 4 (uniqueness) and its proof (4-11)-(4-13): paths under COR = 1, weak solutions, "
    "(4-12)",
    &run_lemma4};

namespace {

constexpr double kGravity = 9.80665;  // Section 5.2
constexpr double kT = kLemma4T;
constexpr int kPairSamples = 4000;  // time samples of the pair files
constexpr double kCoincident = 1e-8;
// The condition-1 pair: u0 = 5, v0 = 0 under gravity meets the floor at t1; w with COR
// sqrt(2) - 1 has (1 + e)^2 t1 = 2 t1, so its apexes meet u's at 2 t1.
const double kT1 = std::sqrt(2 * 5.0 / kGravity);
const double kCorCondition1 = std::sqrt(2.0) - 1;

PathDistance path_distance(const std::vector<double>& h, std::vector<double> sup) {
  PathDistance d;
  std::vector<double> fit_h, fit_sup;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (sup[i] >= kCoincident) {
      fit_h.push_back(h[i]);
      fit_sup.push_back(sup[i]);
    }
  }
  d.fit = fit_order(fit_h, fit_sup);
  d.coincident = h.size() - fit_h.size();
  d.sup = std::move(sup);
  return d;
}

std::string paths_csv(const PathRun& run) {
  std::ostringstream csv;
  csv << "h,direct_mj,direct_exact,mj_exact\n";
  for (std::size_t i = 0; i < run.h.size(); ++i)
    csv << round_trip(run.h[i]) << ',' << round_trip(run.direct_mj.sup[i]) << ','
        << round_trip(run.direct_exact.sup[i]) << ',' << round_trip(run.mj_exact.sup[i]) << '\n';
  return csv.str();
}

// A distance's fit, its coincident points, its largest value and its largest value over h.
void insert_distance_summary(toml::table& out, const std::string& key, const std::vector<double>& h,
                             const PathDistance& d) {
  double bound = 0, largest = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    bound = std::fmax(bound, d.sup[i] / h[i]);
    largest = std::fmax(largest, d.sup[i]);
  }
  out.insert(key + "_fit", order_fit_table(d.fit));
  out.insert(key + "_coincident", static_cast<std::int64_t>(d.coincident));
  out.insert(key + "_max", largest);
  out.insert(key + "_over_h_max", bound);
}

// The same with the distances themselves.
void insert_distance(toml::table& out, const std::string& key, const std::vector<double>& h,
                     const PathDistance& d) {
  out.insert(key, toml_array(d.sup));
  insert_distance_summary(out, key, h, d);
}

toml::table paths_table(const PathRun& run) {
  toml::table out{{"h", toml_array(run.h)},
                  {"direct_mj", toml_array(run.direct_mj.sup)},
                  {"direct_exact", toml_array(run.direct_exact.sup)},
                  {"mj_exact", toml_array(run.mj_exact.sup)}};
  for (const auto& [key, d] :
       {std::pair{"direct_mj", &run.direct_mj}, std::pair{"direct_exact", &run.direct_exact},
        std::pair{"mj_exact", &run.mj_exact}})
    insert_distance_summary(out, key, run.h, *d);
  return out;
}

std::string as_printed_csv(const std::vector<double>& h, const PathDistance& d) {
  std::ostringstream csv;
  csv << "h,direct_paper_exact\n";
  for (std::size_t i = 0; i < h.size(); ++i)
    csv << round_trip(h[i]) << ',' << round_trip(d.sup[i]) << '\n';
  return csv.str();
}

std::string perturbation_csv(const PerturbationRun& run) {
  std::ostringstream csv;
  csv << "delta,f0_u0,f0_v0,g_u0,g_v0\n";
  for (std::size_t j = 0; j < run.delta.size(); ++j)
    csv << round_trip(run.delta[j]) << ',' << round_trip(run.f0_u0[j]) << ','
        << round_trip(run.f0_v0[j]) << ',' << round_trip(run.g_u0[j]) << ','
        << round_trip(run.g_v0[j]) << '\n';
  return csv.str();
}

toml::table perturbation_table(const PerturbationRun& run) {
  toml::table out{{"delta", toml_array(run.delta)}};
  for (const auto& [name, sup] : {std::pair{"f0_u0", &run.f0_u0}, std::pair{"f0_v0", &run.f0_v0},
                                  std::pair{"g_u0", &run.g_u0}, std::pair{"g_v0", &run.g_v0}}) {
    double lipschitz = 0;
    for (std::size_t j = 0; j < run.delta.size(); ++j)
      lipschitz = std::fmax(lipschitz, (*sup)[j] / run.delta[j]);
    out.insert(name, toml::table{{"sup", toml_array(*sup)},
                                 {"fit", order_fit_table(fit_order(run.delta, *sup))},
                                 {"sup_over_delta_max", lipschitz}});
  }
  return out;
}

// Part 2: the weak formulation on one exact solution.
toml::table weak_table(const Model& model, const State& initial, double T) {
  const WeakSolutionCheck c = check_weak_solution(ExactSolution(model, initial), model, T);
  return toml::table{{"cor", newton_e(contact_law(model, kElasticReading))},
                     {"f", model.f},
                     {"u0", initial.u},
                     {"v0", initial.v},
                     {"T", T},
                     {"min_gap", c.min_gap},
                     {"min_cell_impulse", c.min_cell_impulse},
                     {"total_impulse", c.total_impulse},
                     {"complementarity", c.complementarity},
                     {"max_weak_residual", c.max_weak_residual},
                     {"max_weak_scale", c.max_weak_scale},
                     {"test_functions", c.test_functions}};
}

// Part 2: COR = 1 and COR = 1/2 from the same data, f = 0; the two gravity solutions of part 4;
// and the paper's gravity scene with COR 0.75 (a Zeno point and a rest phase).
toml::table weak_tables() {
  const Model gravity_1{.f = -kGravity, .cor = 1.0};
  return toml::table{
      {"f0_cor_1", weak_table(Model{.cor = 1.0}, {5.0, -1.0}, kT)},
      {"f0_cor_0_5", weak_table(Model{.cor = 0.5}, {5.0, -1.0}, kT)},
      {"g_v0_cor_1", weak_table(gravity_1, {5.0, 0.0}, 3.0)},
      {"g_v0_cor_sqrt2_1",
       weak_table(Model{.f = -kGravity, .cor = kCorCondition1}, {5.0, 0.0}, 3.0)},
      {"g_cor_0_75", weak_table(Model{.f = -kGravity, .cor = 0.75}, {5.0, -1.0}, kT)}};
}

std::string pair_csv(const SolutionPair& pair) {
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  std::ostringstream csv;
  csv << "t,u,w,u_t,w_t,lhs,paper_rhs,force_terms,dropped_n1_u,dropped_n2_w,paper_413\n";
  for (int i = 0; i <= kPairSamples; ++i) {
    const double t = pair.T * i / kPairSamples;
    const State a = u.at(t), b = w.at(t);
    const EnergyIdentity412 r = energy_identity_412(u, w, pair.model_u, t);
    csv << round_trip(t) << ',' << round_trip(a.u) << ',' << round_trip(b.u) << ','
        << round_trip(a.v) << ',' << round_trip(b.v) << ',' << round_trip(r.lhs) << ','
        << round_trip(r.paper_rhs) << ',' << round_trip(r.force_terms) << ','
        << round_trip(r.dropped_n1_u) << ',' << round_trip(r.dropped_n2_w) << ','
        << round_trip(r.paper_413) << '\n';
  }
  return csv.str();
}

template <class Of>
toml::array column(const std::vector<double>& at, Of of) {
  toml::array out;
  for (double t : at) out.push_back(of(t));
  return out;
}

toml::table pair_table(const SolutionPair& pair) {
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  const std::vector<EnergyIdentity412> terms = identities_at(pair);
  const auto term = [&](double EnergyIdentity412::*member) {
    toml::array out;
    for (const EnergyIdentity412& r : terms) out.push_back(r.*member);
    return out;
  };
  return toml::table{{"sup_distance", sup_distance(u, w, pair.T)},
                     {"t", toml_array(pair.at)},
                     {"u", column(pair.at, [&](double t) { return u.at(t).u; })},
                     {"w", column(pair.at, [&](double t) { return w.at(t).u; })},
                     {"u_t", column(pair.at, [&](double t) { return u.at(t).v; })},
                     {"w_t", column(pair.at, [&](double t) { return w.at(t).v; })},
                     {"lhs", term(&EnergyIdentity412::lhs)},
                     {"paper_rhs", term(&EnergyIdentity412::paper_rhs)},
                     {"force_terms", term(&EnergyIdentity412::force_terms)},
                     {"dropped_n1_u", term(&EnergyIdentity412::dropped_n1_u)},
                     {"dropped_n2_w", term(&EnergyIdentity412::dropped_n2_w)},
                     {"paper_413", term(&EnergyIdentity412::paper_413)}};
}

}  // namespace

std::vector<PathScene> path_scenes(const Lemma4Options& options) {
  // u0 = 5, v0 = -1, f = 0 meets the floor at t* = 5.
  return {{"f0",
           Model{},
           {5.0, -1.0},
           at_least(aligned_steps(options.free.steps(), 5.0), options.h_floor)},
          {"f0_cor_1",
           Model{.cor = 1.0},
           {5.0123, -1.0},
           at_least(options.free.steps(), options.h_floor)},
          {"gravity",
           Model{.f = -kGravity, .cor = 1.0},
           {5.0, -1.0},
           at_least(options.gravity.steps(), options.h_floor)}};
}

PathRun run_paths(const PathScene& scene) {
  std::vector<double> dm, de, me;
  for (double h : scene.h) {
    const Scene direct = make_scene(scene.model, scene.initial, kT, h, DirectParams{});
    const Scene mj = make_scene(scene.model, scene.initial, kT, h, MoreauJeanParams{});
    dm.push_back(sup_distance(direct, MoreauJeanParams{}));
    de.push_back(sup_distance(direct, ExactParams{}));
    me.push_back(sup_distance(mj, ExactParams{}));
  }
  return PathRun{scene.h, path_distance(scene.h, std::move(dm)),
                 path_distance(scene.h, std::move(de)), path_distance(scene.h, std::move(me))};
}

PathDistance run_paths_as_printed(const PathScene& scene) {
  std::vector<double> sup;
  for (double h : scene.h) {
    const Scene printed = make_scene(scene.model, scene.initial, kT, h,
                                     DirectParams{.free_flight = FreeFlightForm::paper});
    sup.push_back(sup_distance(printed, ExactParams{}));
  }
  return path_distance(scene.h, std::move(sup));
}

PerturbationRun run_perturbation() {
  const State base{5.0, -1.0};
  const ExactSolution f0(Model{.cor = 1.0}, base);
  const Model gravity{.f = -kGravity, .cor = 1.0};
  const ExactSolution g(gravity, base);
  PerturbationRun run;
  for (int k = 1; k <= 8; ++k) {
    const double delta = std::pow(10.0, -k);
    run.delta.push_back(delta);
    run.f0_u0.push_back(
        sup_distance(f0, ExactSolution(Model{.cor = 1.0}, {5.0 + delta, -1.0}), kT));
    run.f0_v0.push_back(
        sup_distance(f0, ExactSolution(Model{.cor = 1.0}, {5.0, -1.0 + delta}), kT));
    run.g_u0.push_back(sup_distance(g, ExactSolution(gravity, {5.0 + delta, -1.0}), kT));
    run.g_v0.push_back(sup_distance(g, ExactSolution(gravity, {5.0, -1.0 + delta}), kT));
  }
  return run;
}

std::vector<SolutionPair> solution_pairs() {
  const Model elastic{.cor = 1.0}, gravity{.f = -kGravity, .cor = 1.0};
  return {{"cor", elastic, {5.0, -1.0}, Model{.cor = 0.5}, {5.0, -1.0}, kT, {2.0, 5.2, 8.0}},
          {"elastic", elastic, {5.0, -1.0}, elastic, {5.5, -1.0}, kT, {2.0, 5.2, 8.0}},
          {"condition1",
           gravity,
           {5.0, 0.0},
           Model{.f = -kGravity, .cor = kCorCondition1},
           {5.0, 0.0},
           3.0,
           {0.0, 0.5 * kT1, 1.5 * kT1, 2 * kT1, 2.5}}};
}

std::vector<EnergyIdentity412> identities_at(const SolutionPair& pair) {
  const ExactSolution u(pair.model_u, pair.u0), w(pair.model_w, pair.w0);
  std::vector<EnergyIdentity412> terms;
  for (double t : pair.at) terms.push_back(energy_identity_412(u, w, pair.model_u, t));
  return terms;
}

toml::table run_lemma4(const ExperimentContext& context, const Lemma4Options& options) {
  toml::table paths;
  for (const PathScene& scene : path_scenes(options)) {
    const PathRun run = run_paths(scene);
    context.write("paths_" + scene.name + ".csv", [&] { return paths_csv(run); });
    toml::table table = paths_table(run);
    if (scene.name == "f0") {
      const PathDistance printed = run_paths_as_printed(scene);
      context.write("paths_f0_as_printed.csv", [&] { return as_printed_csv(run.h, printed); });
      insert_distance(table, "direct_paper_exact", run.h, printed);
    }
    paths.insert(scene.name, std::move(table));
  }
  const PerturbationRun perturbation = run_perturbation();
  context.write("perturbation.csv", [&] { return perturbation_csv(perturbation); });
  toml::table pairs;
  for (const SolutionPair& pair : solution_pairs()) {
    context.write("pair_" + pair.name + ".csv", [&] { return pair_csv(pair); });
    pairs.insert(pair.name, pair_table(pair));
  }
  return toml::table{{"paths", paths},
                     {"perturbation", perturbation_table(perturbation)},
                     {"weak", weak_tables()},
                     {"pairs", pairs},
                     {"condition1", toml::table{{"t1", kT1},
                                                {"common_zero_velocity_time", 2 * kT1},
                                                {"cor_w", kCorCondition1}}}};
}

toml::table run_lemma4(const ExperimentContext& context) {
  return run_lemma4(context, Lemma4Options{});
}

}  // namespace impact::lemma4
