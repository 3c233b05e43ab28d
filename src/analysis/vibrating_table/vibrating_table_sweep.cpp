#include "analysis/vibrating_table/vibrating_table_sweep.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace impact::vibrating_table {

namespace {

// The scene that continues `run` of `scene`: the same table, the clock carried on in the phase.
TableScene continuation(const TableScene& scene, const TableRun& run, double h) {
  TableScene next = scene;
  next.phase = std::fmod(scene.phase + scene.omega * static_cast<double>(run.steps) * h,
                         2 * std::numbers::pi);
  next.initial = run.final_state;
  return next;
}

SweepPoint sweep_point(const TableScene& scene, const MethodParams& method, double h,
                       const SweepSettings& settings) {
  try {
    const TableRun run =
        run_table(scene, method, h, settings.periods, settings.transient, settings.max_events);
    return {scene.gamma,
            classify_table_run(run, scene, settings.tolerance),
            run.events,
            continuation(scene, run, h),
            {}};
  } catch (const std::runtime_error& failure) {
    SweepPoint point{scene.gamma, {}, {}, scene, failure.what()};
    point.classification.regime = TableRegime::failed;
    return point;
  }
}

}  // namespace

std::vector<SweepPoint> sweep_table(const TableScene& start, const MethodParams& method, double h,
                                    const std::vector<double>& gammas,
                                    const SweepSettings& settings) {
  std::vector<SweepPoint> points;
  points.reserve(gammas.size());
  TableScene scene = start;
  for (double gamma : gammas) {
    scene.gamma = gamma;
    scene.initial.v *= 1 + settings.kick;
    points.push_back(sweep_point(scene, method, h, settings));
    scene = points.back().end;
  }
  return points;
}

std::size_t failed_points(const std::vector<SweepPoint>& sweep) {
  return static_cast<std::size_t>(std::count_if(
      sweep.begin(), sweep.end(),
      [](const SweepPoint& p) { return p.classification.regime == TableRegime::failed; }));
}

std::vector<double> gamma_grid(double from, double to, double step) {
  std::vector<double> grid;
  const long count = std::lround(std::floor((to - from) / step + 1e-9));
  for (long k = 0; k <= count; ++k) grid.push_back(from + static_cast<double>(k) * step);
  return grid;
}

double fit_period_doubling(const std::vector<SweepPoint>& sweep, double s_lo, double s_hi,
                           int* used) {
  std::vector<const SweepPoint*> ascending;
  for (const SweepPoint& p : sweep) ascending.push_back(&p);
  std::sort(ascending.begin(), ascending.end(),
            [](const SweepPoint* a, const SweepPoint* b) { return a->gamma < b->gamma; });
  // The block of points right above the last one with a split below s_lo, up to the first above
  // s_hi: the growing period-2 branch (a time-stepper's grid can split a period-1 orbit a little,
  // by less than s_lo; sticking points have no such branch and end the block).
  std::vector<double> xs, ys;
  for (const SweepPoint* p : ascending) {
    const TableClassification& c = p->classification;
    if (c.regime == TableRegime::failed) continue;
    if (c.split < s_lo || c.regime == TableRegime::sticking || c.regime == TableRegime::resting) {
      xs.clear();
      ys.clear();
    } else if (c.split <= s_hi) {
      xs.push_back(p->gamma);
      ys.push_back(c.split * c.split);
    } else if (!xs.empty()) {
      break;
    }
  }
  // Gamma against y = split^2 by least squares (Eigen): Gamma = Gamma_pd + c1 y, plus c2 y^2 from
  // four points on, which absorbs the curvature of the branch away from the threshold.
  if (used) *used = static_cast<int>(xs.size());
  if (xs.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Index rows = static_cast<Eigen::Index>(xs.size()), cols = xs.size() < 4 ? 2 : 3;
  Eigen::MatrixXd design(rows, cols);
  Eigen::VectorXd gamma(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const double y = ys[static_cast<std::size_t>(r)];
    design(r, 0) = 1.0;
    design(r, 1) = y;
    if (cols == 3) design(r, 2) = y * y;
    gamma(r) = xs[static_cast<std::size_t>(r)];
  }
  return design.colPivHouseholderQr().solve(gamma)(0);
}

double split_crossing(const std::vector<SweepPoint>& sweep, double level) {
  std::vector<const SweepPoint*> ascending;
  for (const SweepPoint& p : sweep) ascending.push_back(&p);
  std::sort(ascending.begin(), ascending.end(),
            [](const SweepPoint* a, const SweepPoint* b) { return a->gamma < b->gamma; });
  std::erase_if(ascending, [](const SweepPoint* p) {
    return p->classification.regime == TableRegime::failed;
  });
  for (std::size_t k = 1; k < ascending.size(); ++k) {
    const double below = ascending[k - 1]->classification.split,
                 above = ascending[k]->classification.split;
    if (below < level && above >= level) {
      const double y0 = below * below, y1 = above * above, x0 = ascending[k - 1]->gamma,
                   x1 = ascending[k]->gamma;
      return x0 + (x1 - x0) * (level * level - y0) / (y1 - y0);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double lowest_period_one(const std::vector<SweepPoint>& sweep, std::size_t* keeps,
                         std::size_t* leaves) {
  std::optional<std::size_t> last;
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    const TableRegime regime = sweep[k].classification.regime;
    if (regime == TableRegime::failed) continue;
    if (regime == TableRegime::period_one) {
      last = k;
    } else if (last) {
      if (keeps) *keeps = *last;
      if (leaves) *leaves = k;
      return sweep[*last].gamma;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double bisect_period_one_end(const SweepPoint& keeps, double leaves, const MethodParams& method,
                             double h, const SweepSettings& settings, int iterations,
                             std::string* failure) {
  double in = keeps.gamma, out = leaves;
  for (int i = 0; i < iterations; ++i) {
    TableScene trial = keeps.end;
    trial.gamma = (in + out) / 2;
    const SweepPoint point = sweep_point(trial, method, h, settings);
    if (point.classification.regime == TableRegime::failed) {
      if (failure) *failure = point.failure;
      break;
    }
    (point.classification.regime == TableRegime::period_one ? in : out) = trial.gamma;
  }
  return in;
}

}  // namespace impact::vibrating_table
