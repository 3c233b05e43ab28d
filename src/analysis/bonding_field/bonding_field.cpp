#include "analysis/bonding_field/bonding_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "impact/output/csv.hpp"
#include "impact/run/run_result.hpp"
#include "scene/read_scene.hpp"

namespace impact::bonding_field {
namespace {

bool no_damage(const Scene& scene, double* top_time);
bool never_lifts(const Scene& scene, double* top_time);

// One map: x across (x_key = x * x_scale), `key` down, from the scene
// experiments/bonding_field/<scene>.toml; `derived` says whether no bond breaks at a point.
struct MapSpec {
  const char* name;
  const char* scene;
  const char* x_key;  // initial.v0, or force.amplitude as Gamma g
  const char* x_name;
  double x_scale;
  const char* key;    // bonding.beta0 or bonding.eps_a
  const char* fixed;  // a further key=value for the whole map, or ""
  double x_low, x_high;
  int x_count;
  double key_low, key_high;
  int key_count;
  bool (*derived)(const Scene&, double* top_time);
  bool iff;       // whether `derived` is also necessary: then bonds break at every point outside
  Fate row_fate;  // the fate whose first x on each row is reported (escape, or debond)
};

constexpr double kG = 9.81;  // the scenes' gravity: Gamma = amplitude / g on the table

constexpr MapSpec kMaps[] = {
    // v0 off the grid of beta0 sqrt(eps_a), so that no point lies on the derived boundary
    {"free_beta0", "free", "initial.v0", "v0", 1.0, "bonding.beta0", "", 0.06, 2.01, 40, 0.05, 1.0,
     20, no_damage, true, Fate::escaped},
    // beta0 = 0.5: with all bonds (beta0 = 1) no v0 up to 5 escapes at these eps_a
    {"free_eps_a", "free", "initial.v0", "v0", 1.0, "bonding.eps_a", "bonding.beta0=0.5", 0.06,
     2.01, 40, 0.05, 1.0, 20, no_damage, true, Fate::escaped},
    {"gravity_beta0", "gravity", "initial.v0", "v0", 1.0, "bonding.beta0", "", 0.06, 2.01, 40, 0.05,
     1.0, 20, no_damage, true, Fate::escaped},
    // The glued ball on the vibrating table: Gamma off 1, where the derived boundary lies; beta0
    // above the scene's debond_below = 0.1. Lifting off (Gamma > 1) need not break a bond.
    {"table_beta0", "table", "force.amplitude", "Gamma", kG, "bonding.beta0", "", 0.05, 5.05, 41,
     0.15, 1.0, 18, never_lifts, false, Fate::debonded},
};

double node(double low, double high, int count, int i) {
  return low + (high - low) * i / (count - 1);
}

struct Point {
  double x, y;
  Fate fate;
  BondFates bonds;
  double beta_T;
  bool no_damage;
  double expected_top;  // half the harmonic return time, inside the no-damage region
};

// Whether no bond breaks on the first flight (the derived region): the top of the well's flight,
// R capped at L, keeps gamma R^2 <= eps_a (bonding.hpp's well_height; the opening grows until the
// top, and past L it stays L). The flight is harmonic, and turns at half of well_return_time, when
// the top is within L too; top_time is NaN otherwise.
bool no_damage(const Scene& scene, double* top_time) {
  const Bonding& b = *scene.model.bonding;
  const double k = b.gamma * b.beta0 * b.beta0, G = -scene.model.f, v0 = scene.initial.v;
  const double top = well_height(k, G, 0.0, v0), reach = std::min(top, b.L);
  *top_time = top <= b.L ? 0.5 * well_return_time(k, G, v0) : std::nan("");
  return b.gamma * reach * reach <= b.eps_a;
}

// The ball at rest on the table (u0 = phi, v0 = 0) under f = -g + a sin(omega t) never leaves it
// while f <= 0 throughout, a <= g (Gamma <= 1): no opening, no bond breaks. No flight, no top.
bool never_lifts(const Scene& scene, double* top_time) {
  *top_time = std::nan("");
  const double a = scene.model.harmonic ? std::fabs(scene.model.harmonic->amplitude) : 0.0;
  return scene.model.f + a <= 0.0;
}

Point run_point(const MapSpec& map, const Scene& scene, double x, double y) {
  const PointSummary s = summarize(scene, false).summary;
  Point p{x, y, Fate::undecided, s.bonds, s.internal_final[kBondFraction], false, 0};
  p.no_damage = map.derived(scene, &p.expected_top);
  // A ball that never left the floor (no capture) and kept its bonds is intact too.
  const bool came_back = !std::isnan(s.bonds.capture) || s.max_u == scene.initial.u;
  if (!std::isnan(s.bonds.escape))
    p.fate = Fate::escaped;
  else if (!std::isnan(s.bonds.debond))
    p.fate = Fate::debonded;
  else if (came_back)
    p.fate = p.beta_T == scene.model.bonding->beta0 ? Fate::intact : Fate::damaged;
  return p;
}

std::string map_csv(const MapSpec& map, const std::vector<Point>& points) {
  std::ostringstream csv;
  const std::string key = std::string(map.key).substr(std::string(map.key).find('.') + 1);
  csv << map.x_name << ',' << key
      << ",fate,capture_time,escape_time,debond_time,beta_T,no_damage\n";
  for (const Point& p : points)
    csv << round_trip(p.x) << ',' << round_trip(p.y) << ',' << static_cast<int>(p.fate) << ','
        << round_trip(p.bonds.capture) << ',' << round_trip(p.bonds.escape) << ','
        << round_trip(p.bonds.debond) << ',' << round_trip(p.beta_T) << ',' << (p.no_damage ? 1 : 0)
        << '\n';
  return csv.str();
}

toml::table run_map(const ExperimentContext& context, const MapSpec& map) {
  const std::string path = context.scene_path("bonding_field", std::string(map.scene) + ".toml");
  std::vector<Point> points;
  std::int64_t fates[5] = {}, inside = 0, changed_inside = 0, unchanged_outside = 0,
               not_monotone = 0;
  double top_error = 0;
  toml::array first_of_fate;
  for (int j = 0; j < map.key_count; ++j) {
    const double y = node(map.key_low, map.key_high, map.key_count, j);
    bool seen = false, monotone = true;
    double first = std::nan("");
    for (int i = 0; i < map.x_count; ++i) {
      const double x = node(map.x_low, map.x_high, map.x_count, i);
      std::vector<std::string> set{std::string(map.x_key) + "=" + round_trip(x * map.x_scale),
                                   std::string(map.key) + "=" + round_trip(y)};
      if (*map.fixed) set.emplace_back(map.fixed);
      const Scene scene = load_scene(path, set);
      const Point p = run_point(map, scene, x, y);
      ++fates[static_cast<int>(p.fate)];
      const double beta0 = scene.model.bonding->beta0;
      if (p.no_damage) {
        ++inside;
        if (p.beta_T != beta0) ++changed_inside;
        if (!std::isnan(p.expected_top))
          top_error = std::max(top_error, std::fabs(p.bonds.capture - p.expected_top));
      } else if (map.iff && p.beta_T == beta0) {
        ++unchanged_outside;
      }
      const bool has = p.fate == map.row_fate;
      if (has && std::isnan(first)) first = x;
      if (seen && !has) monotone = false;
      seen = seen || has;
      points.push_back(p);
    }
    first_of_fate.push_back(first);
    if (!monotone) ++not_monotone;
  }
  const std::string word = map.row_fate == Fate::escaped ? "escape" : "debond";
  context.write(std::string(map.name) + ".csv", [&] { return map_csv(map, points); });
  toml::table out{{"points", static_cast<std::int64_t>(points.size())},
                  {"intact", fates[0]},
                  {"damaged", fates[1]},
                  {"debonded", fates[2]},
                  {"escaped", fates[3]},
                  {"undecided", fates[4]},
                  {"no_damage_points", inside},
                  {"no_damage_beta_changed", changed_inside},
                  {"capture_time_max_error", top_error}};
  if (map.iff) out.insert("damage_predicted_beta_unchanged", unchanged_outside);
  out.insert(word + "_not_monotone_rows", not_monotone);
  out.insert("first_" + word + "_" + map.x_name, first_of_fate);
  return out;
}

}  // namespace

toml::table run_bonding_field(const ExperimentContext& context) {
  toml::table maps;
  for (const MapSpec& map : kMaps) maps.insert(map.name, run_map(context, map));
  return toml::table{{"bonding_field", maps}};
}

const Experiment kBondingFieldExperiment{
    "bonding_field",
    "The bonding field (beyond the paper): capture, escape and debond over (v0, beta0) and (v0, "
    "eps_a), with and without gravity",
    &run_bonding_field};

}  // namespace impact::bonding_field
