#include "analysis/laplace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/quadrature.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"

namespace impact {

namespace {

// Relative accuracy asked of each piece. GK21 on a piece where w is smooth meets it with one or
// two subdivisions; the pieces of the sampled interpolants are a line times e^{-sr}, integrated to
// round-off by one rule.
constexpr double kEpsRel = 1e-12;
constexpr std::size_t kLimit = 200;
// Beyond s t = 60 a bounded w contributes less than e^{-60} / s ~ 1e-26 / s times its size.
constexpr double kNegligibleExponent = 60.0;
// Impacts taken as breakpoints of the exact energy: a Zeno sequence with e <= 0.9 has lost all
// but e^1000 < 1e-45 of its speed after 500 impacts.
constexpr std::int64_t kMaxBreakpoints = 500;

void check_arguments(double s) {
  if (!(s > 0) || !std::isfinite(s))
    throw std::invalid_argument("laplace_transform needs a finite s > 0, got " + round_trip(s));
}

// Neumaier's compensated sum: a transform of 40000 samples adds 40000 pieces, whose plain sum
// would carry ~sqrt(40000) eps = 2e-14 of accumulated rounding, above the quadrature's own error.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    compensation_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0, compensation_ = 0;
};

// The integrand of one piece in the local time r = t - a: w(a + r) e^{-sr}. The factor e^{-sa} is
// applied to the piece's integral, so that every piece is integrated to a relative accuracy.
struct Shifted {
  const std::function<double(double)>& w;
  double a, s;
  double operator()(double r) const {
    const double decay = std::exp(-s * r);
    return decay == 0.0 ? 0.0 : w(a + r) * decay;
  }
};

// The interpolant on one step in the local time r in [0, h]: w0 + slope r, times e^{-sr}.
struct Line {
  double w0, slope, s;
  double operator()(double r) const { return (w0 + slope * r) * std::exp(-s * r); }
};

}  // namespace

LaplaceValue laplace_transform(const std::function<double(double)>& w,
                               std::vector<double> breakpoints, double s) {
  check_arguments(s);
  std::erase_if(breakpoints, [](double b) { return !(b > 0) || !std::isfinite(b); });
  std::sort(breakpoints.begin(), breakpoints.end());
  breakpoints.erase(std::unique(breakpoints.begin(), breakpoints.end()), breakpoints.end());

  Quadrature quadrature(kLimit);
  LaplaceValue out;
  CompensatedSum value;
  // Each piece is integrated in its local time and scaled by e^{-sa}; it is asked for kEpsRel
  // relative to its own size or to what the earlier pieces add up to, whichever is less strict,
  // so that a late piece worth e^{-50} of the total costs no more than its share.
  auto integrate = [&](double a, double b) {
    const double scale = std::exp(-s * a);
    if (scale == 0.0) return false;  // this piece and all later ones underflow
    Shifted piece{w, a, s};
    const Quadrature::Rule rule{kEpsRel * std::fabs(value.value()) / scale, kEpsRel,
                                GSL_INTEG_GAUSS21};
    const std::string what = "laplace_transform on [" + round_trip(a) + ", " + round_trip(b) + "]";
    double abserr = 0;
    const double result = std::isinf(b)
                              ? quadrature.integrate_to_infinity(piece, 0.0, rule, what, &abserr)
                              : quadrature.integrate(piece, 0.0, b - a, {}, rule, what, &abserr);
    value.add(scale * result);
    out.abserr += scale * abserr;
    return true;
  };
  double a = 0.0;
  bool more = true;
  for (double b : breakpoints) {
    more = integrate(a, b);
    if (!more) break;
    a = b;
  }
  if (more) integrate(a, std::numeric_limits<double>::infinity());
  out.value = value.value();
  return out;
}

LaplaceValue laplace_transform_samples(std::span<const double> samples, double h,
                                       Interpolation interpolation, double s, double tail_sup) {
  check_arguments(s);
  if (!(h > 0) || samples.size() < 2)
    throw std::invalid_argument("laplace_transform_samples needs h > 0 and two samples");
  const std::size_t n = samples.size() - 1;
  const auto negligible = static_cast<std::size_t>(std::ceil(kNegligibleExponent / (s * h)));
  const std::size_t stop = std::min(n, negligible);

  Quadrature quadrature(kLimit);
  LaplaceValue out;
  CompensatedSum value;
  for (std::size_t l = 0; l < stop; ++l) {
    const double w_next = samples[l + 1];
    Line line = interpolation == Interpolation::linear
                    ? Line{samples[l], (w_next - samples[l]) / h, s}
                    : Line{w_next, 0.0, s};
    // t_l = l h exactly, as on the solvers' grid (model.hpp).
    const double scale = std::exp(-s * (static_cast<double>(l) * h));
    const Quadrature::Rule rule{kEpsRel * std::fabs(value.value()) / scale, kEpsRel,
                                GSL_INTEG_GAUSS15};
    double abserr = 0;
    const double result =
        quadrature.integrate(line, 0.0, h, {}, rule, "laplace_transform_samples", &abserr);
    value.add(scale * result);
    out.abserr += scale * abserr;
  }
  out.value = value.value();
  double sup = std::fabs(tail_sup);
  for (std::size_t l = stop + 1; l <= n; ++l) sup = std::fmax(sup, std::fabs(samples[l]));
  out.tail_bound = sup * std::exp(-s * (static_cast<double>(stop) * h)) / s;
  return out;
}

double laplace_jump_signature(std::span<const Jump> jumps, double s) {
  double sum = 0;
  for (const Jump& j : jumps) sum += j.size * std::exp(-s * j.time);
  return sum;
}

std::vector<Jump> exact_energy_jumps(const Model& model, const ExactSolution& exact, double horizon,
                                     std::int64_t max_impacts) {
  // Newton's law v+ = -e v- at impact k turns V_k^2 / 2 - f phi into e^2 V_k^2 / 2 - f phi.
  const double e = newton_e(contact_law(model, kElasticReading));
  std::vector<Jump> jumps;
  if (e == 1.0) return jumps;
  for (std::int64_t k = 1; k <= max_impacts; ++k) {
    const std::optional<double> t = exact.impact_time(k);
    if (!t || *t > horizon) break;
    const double V = *exact.impact_speed(k);
    jumps.push_back({*t, -0.5 * (1 - e) * (1 + e) * V * V});
  }
  return jumps;
}

Lemma1Point lemma1_exact(const Model& model, const State& initial, double s) {
  const ExactSolution exact(model, initial);
  std::vector<double> breakpoints;
  for (std::int64_t k = 1; k <= kMaxBreakpoints; ++k) {
    const std::optional<double> t = exact.impact_time(k);
    if (!t) break;
    breakpoints.push_back(*t);
  }
  if (auto rest = exact.rest_time()) breakpoints.push_back(*rest);
  const std::function<double(double)> E = [&](double t) { return energy(model, exact.at(t)); };
  const LaplaceValue L = laplace_transform(E, breakpoints, s);
  const std::vector<Jump> jumps =
      exact_energy_jumps(model, exact, kNegligibleExponent / s, kMaxBreakpoints);
  const double E0 = energy(model, initial), scale = std::fabs(E0);
  return {s, (s * L.value - E0) / scale, laplace_jump_signature(jumps, s) / scale,
          s * L.abserr / scale, s * L.tail_bound / scale};
}

Lemma1Point lemma1_samples(std::span<const double> energies, double h, Interpolation interpolation,
                           double s, double tail_sup) {
  const LaplaceValue L = laplace_transform_samples(energies, h, interpolation, s, tail_sup);
  std::vector<Jump> jumps;
  for (std::size_t l = 0; l + 1 < energies.size(); ++l)
    if (energies[l + 1] != energies[l])
      jumps.push_back({static_cast<double>(l) * h, energies[l + 1] - energies[l]});
  const double E0 = energies[0], scale = std::fabs(E0);
  return {s, (s * L.value - E0) / scale, laplace_jump_signature(jumps, s) / scale,
          s * L.abserr / scale, s * L.tail_bound / scale};
}

std::vector<double> energy_samples(const Scene& scene) {
  AnyStepper stepper = make_stepper(scene);
  std::vector<double> energies;
  energies.reserve(static_cast<std::size_t>(scene.grid.steps) + 1);
  simulate(stepper, scene.initial, scene.grid, [&](std::int64_t, const State& s, const StepInfo&) {
    energies.push_back(energy(scene.model, s));
  });
  return energies;
}

}  // namespace impact
