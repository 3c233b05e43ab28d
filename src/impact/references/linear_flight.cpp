// The closed-form flight under a linear force and its bounds (linear_flight.hpp).
#include "impact/references/linear_flight.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace impact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The bounds' widening for their own rounding.
constexpr double kBoundMargin = 1.0 + 0x1p-30;
// 2 pi in two parts: the double nearest it, and the rest.
constexpr double kTwoPiHigh = 6.283185307179586232, kTwoPiLow = 2.4492935982947064e-16;
// The Taylor series of the fundamental solutions are used where |c| tau <= 1 and |k| tau^2 <= 1:
// there the n-th term is at most 2^n/n! of the first, and 28 terms reach 1e-21 of it.
constexpr int kTaylorTerms = 28;
// Below |q| tau^2 = 0.01 C and S are their series in q tau^2 (8 terms reach rounding).
constexpr double kSeriesRegime = 0.01;

// (e^z - 1)/z, accurate for every z (e^z - 1 from expm1 and 1 - cos y = 2 sin^2(y/2)).
std::complex<double> phi1(std::complex<double> z) {
  if (z == 0.0) return 1.0;
  const double x = z.real(), y = z.imag(), s = std::sin(y / 2);
  const std::complex<double> em1(std::expm1(x) * std::cos(y) - 2 * s * s,
                                 std::exp(x) * std::sin(y));
  return em1 / z;
}

double phi1(double x) {
  return x == 0.0 ? 1.0 : std::expm1(x) / x;
}

}  // namespace

double LinearForce::at(double t, double u, double v) const {
  const double harmonic = amplitude == 0.0 ? 0.0 : amplitude * std::sin(omega * t + phase);
  return -k * (u - u_eq) - c * v + f0 + harmonic;
}

double reduced_angle(double omega, double t, double phase) {
  const double p = omega * t, p_error = std::fma(omega, t, -p);
  const double turns = std::nearbyint(p / kTwoPiHigh);
  const double r = std::fma(-turns, kTwoPiHigh, p);
  return (r - turns * kTwoPiLow + p_error) + phase;
}

LinearFlight::LinearFlight(const LinearForce& force, double t_a, double u_a, double v_a)
    : force_(force), t_a_(t_a), u_a_(u_a), v_a_(v_a) {
  const LinearForce& f = force;
  if (!std::isfinite(f.k) || !std::isfinite(f.c) || !std::isfinite(f.u_eq) ||
      !std::isfinite(f.f0) || !std::isfinite(f.amplitude) || !std::isfinite(f.omega) ||
      !std::isfinite(f.phase) || !std::isfinite(t_a) || !std::isfinite(u_a) || !std::isfinite(v_a))
    throw std::invalid_argument(
        "linear flight: k, c, u_eq, f0, the harmonic term and the "
        "anchor must be finite");
  harmonic_ = f.amplitude != 0.0;
  if (harmonic_ && !(f.omega > 0.0))
    throw std::invalid_argument("linear flight: a harmonic term needs omega > 0");
  F_ = f.f0 - f.k * (u_a - f.u_eq);
  q_ = f.k - f.c * f.c / 4;
  root_ = std::sqrt(std::fabs(q_));
  if (q_ < 0.0) {
    // The root of larger size without cancellation, the other from their product k.
    fast_ = -f.c / 2 - std::copysign(root_, f.c == 0.0 ? 1.0 : f.c);
    slow_ = f.k / fast_;
  }
  if (!harmonic_) return;
  const double angle = reduced_angle(f.omega, t_a, f.phase);
  sin_a_ = std::sin(angle);
  cos_a_ = std::cos(angle);
  const double w2 = f.omega * f.omega, detuning = f.k - w2, damping = f.c * f.omega;
  delta_ = detuning * detuning + damping * damping;
  duhamel_ = q_ > 0.0 && f.c >= 0.0 && std::sqrt(delta_) < std::fmax(std::fabs(f.k), w2) / 8;
  P_ = f.amplitude * detuning / delta_;
  Q_ = -f.amplitude * damping / delta_;
}

LinearFlight::Fundamental LinearFlight::fundamental(double tau) const {
  const double k = force_.k, c = force_.c;
  Fundamental fs;
  if (tau == 0.0) {
    fs.series_response = true;  // R = R' = 0
    return fs;
  }
  const double ct = c * tau, kt2 = k * tau * tau, wt = harmonic_ ? force_.omega * tau : 0.0;
  if (std::fabs(ct) <= 1.0 && std::fabs(kt2) <= 1.0) {
    // Each solution as sum b_n, b_n = a_n tau^n its Taylor terms, from
    // (n+2)(n+1) b_(n+2) = -c tau (n+1) b_(n+1) - k tau^2 b_n + tau^2 (forcing's n-th term):
    // the forcing is 0 (p1, p2), 1 (Psi) and a sin(theta_a + omega tau) (R, while omega tau <= 1,
    // so that a short flight's displacement is accurate relative to itself).
    fs.series_response = std::fabs(wt) <= 1.0;
    double p1[2] = {1.0, 0.0}, p2[2] = {0.0, tau}, ps[2] = {0.0, 0.0}, rs[2] = {0.0, 0.0};
    fs = {1.0, tau, 0.0, 1.0, 0.0, fs.series_response, 0.0, 0.0};
    double forcing =
        fs.series_response ? force_.amplitude * tau * tau : 0.0;  // a tau^2 (w tau)^n/n!
    const double cycle[4] = {sin_a_, cos_a_, -sin_a_, -cos_a_};   // sin(theta_a + n pi/2)
    for (int n = 0; n < kTaylorTerms; ++n) {
      const double denominator = (n + 2.0) * (n + 1.0);
      const auto next = [&](const double* b, double source) {
        return (source - ct * (n + 1) * b[1] - kt2 * b[0]) / denominator;
      };
      const double n1 = next(p1, 0.0), n2 = next(p2, 0.0);
      const double np = next(ps, n == 0 ? tau * tau : 0.0);
      const double nr = next(rs, forcing * cycle[n % 4]);
      forcing *= wt / (n + 1);
      fs.p1 += n1;
      fs.p2 += n2;
      fs.psi += np;
      fs.r += nr;
      fs.dp1 += (n + 2) * n1 / tau;
      fs.dp2 += (n + 2) * n2 / tau;
      fs.dr += (n + 2) * nr / tau;
      p1[0] = p1[1], p1[1] = n1;
      p2[0] = p2[1], p2[1] = n2;
      ps[0] = ps[1], ps[1] = np;
      rs[0] = rs[1], rs[1] = nr;
    }
    return fs;
  }
  const double qt2 = q_ * tau * tau;
  if (q_ < 0.0 && std::fabs(qt2) >= kSeriesRegime) {
    const double ea = std::exp(fast_ * tau), eb = std::exp(slow_ * tau);
    const double d = -2 * std::copysign(root_, force_.c == 0.0 ? 1.0 : force_.c);  // fast - slow
    fs.p2 = (ea - eb) / d;
    fs.p1 = (fast_ * eb - slow_ * ea) / d;
    fs.dp2 = (fast_ * ea - slow_ * eb) / d;
    fs.dp1 = -k * fs.p2;
    fs.psi = tau * (phi1(fast_ * tau) - phi1(slow_ * tau)) / d;
    return fs;
  }
  double C = 0, S = 0;
  if (std::fabs(qt2) < kSeriesRegime) {
    double term_c = 1.0, term_s = 1.0;
    for (int n = 0; n < 8; ++n) {
      C += term_c;
      S += term_s;
      term_c *= -qt2 / ((2 * n + 1) * (2 * n + 2));
      term_s *= -qt2 / ((2 * n + 2) * (2 * n + 3));
    }
    S *= tau;
  } else {
    C = std::cos(root_ * tau);
    S = std::sin(root_ * tau) / root_;
  }
  const double e = std::exp(-ct / 2), E0 = e * C, E1 = e * S;
  fs.p1 = E0 + c / 2 * E1;
  fs.p2 = E1;
  fs.dp1 = -k * E1;
  fs.dp2 = E0 - c / 2 * E1;
  // Here k tau^2 > 1/4 (outside the Taylor regime with q > 0 or |q| tau^2 small), so 1 - p1 is
  // not a difference of nearly equal numbers.
  fs.psi = (1 - fs.p1) / k;
  return fs;
}

void LinearFlight::angle(double tau, double& s, double& c) const {
  const double x = force_.omega * tau, sx = std::sin(x), cx = std::cos(x);
  s = sin_a_ * cx + cos_a_ * sx;
  c = cos_a_ * cx - sin_a_ * sx;
}

void LinearFlight::steady(double s, double c, double& y, double& dy) const {
  y = P_ * s + Q_ * c;
  dy = force_.omega * (P_ * c - Q_ * s);
}

void LinearFlight::harmonic_response(double tau, const Fundamental& fs, double s, double c,
                                     double& r, double& dr) const {
  if (!duhamel_) {
    double y0, dy0, y, dy;
    steady(sin_a_, cos_a_, y0, dy0);
    steady(s, c, y, dy);
    r = y - y0 * fs.p1 - dy0 * fs.p2;
    dr = dy - y0 * fs.dp1 - dy0 * fs.dp2;
    return;
  }
  using namespace std::complex_literals;
  const double w = force_.omega, half_c = force_.c / 2;
  const std::complex<double> z1(-half_c * tau, -(w - root_) * tau);
  const std::complex<double> z2(-half_c * tau, -(w + root_) * tau);
  const std::complex<double> I = tau * (phi1(z1) - phi1(z2)) / (2.0i * root_);
  const std::complex<double> rotated = std::complex<double>(c, s) * I;  // e^(i theta(tau)) I
  r = force_.amplitude * rotated.imag();
  dr = force_.amplitude * (w * rotated.real() + fs.p2 * sin_a_);
}

FlightMotion LinearFlight::relative(double t) const {
  const double tau = t - t_a_;
  const Fundamental fs = fundamental(tau);
  double r = fs.r, dr = fs.dr, forcing = 0.0;
  if (harmonic_) {
    double s, c;
    angle(tau, s, c);
    if (!fs.series_response) harmonic_response(tau, fs, s, c, r, dr);
    forcing = force_.amplitude * s;
  }
  const double w = v_a_ * fs.p2 + F_ * fs.psi + r;
  const double v = v_a_ * fs.dp2 + F_ * fs.p2 + dr;
  return {w, v, -force_.k * w - force_.c * v + F_ + forcing};
}

double LinearFlight::window() const {
  const double scale =
      std::fmax(std::fmax(harmonic_ ? force_.omega : 0.0, std::sqrt(std::fabs(force_.k))),
                std::fabs(force_.c));
  return scale > 0.0 ? std::numbers::pi / (2 * scale) : kInfinity;
}

AccelerationBound LinearFlight::acceleration_bound(double t) const {
  const LinearForce& f = force_;
  const FlightMotion m = at(t);
  const double a = std::fabs(f.amplitude);
  if (f.k >= 0.0 && f.c >= 0.0 && !duhamel_) {
    double yp = 0.0, dyp = 0.0, steady_bound = 0.0;
    if (harmonic_) {
      double s, c;
      angle(t - t_a_, s, c);
      steady(s, c, yp, dyp);
      steady_bound = f.omega * f.omega * a / std::sqrt(delta_);
    }
    const bool free_fall = f.k == 0.0 && f.c == 0.0;  // u_c = f0 tau^2/2
    const double yh2 = m.a - (free_fall ? f.f0 : 0.0) + f.omega * f.omega * yp;
    const double yh1 = f.k > 0.0 ? m.v - dyp : 0.0;
    const double B =
        std::sqrt(yh2 * yh2 + f.k * yh1 * yh1) + steady_bound + (free_fall ? std::fabs(f.f0) : 0.0);
    return {B * kBoundMargin, kInfinity};
  }
  if (f.k > 0.0 && f.c >= 0.0) {
    const double W = window(), y = m.u - (f.u_eq + f.f0 / f.k);
    const double E = m.v * m.v + f.k * y * y;
    const double B = std::sqrt(f.k + f.c * f.c) * (std::sqrt(E) + a * W) + a;
    return {B * kBoundMargin, t + W};
  }
  const double growth = std::sqrt(1 + f.k * f.k + f.c * f.c);
  const double W = std::fmin(window(), std::numbers::ln2 / growth);
  const double x1 = f.k != 0.0 ? m.u - (f.u_eq + f.f0 / f.k) : 0.0;
  const double x2 = f.k != 0.0 ? m.v : m.v - f.f0 / f.c;
  const double B =
      std::sqrt(f.k * f.k + f.c * f.c) * std::exp(growth * W) * (std::hypot(x1, x2) + a * W) + a;
  return {B * kBoundMargin, t + W};
}

DepartureBounds LinearFlight::departure_bounds(double t) const {
  const AccelerationBound b = acceleration_bound(t);
  const double W = std::fmin(b.until - t, window());
  if (!(W < kInfinity)) return {0.0, 0.0, kInfinity};  // a constant force: u''' = 0
  const LinearForce& f = force_;
  const double a = std::fabs(f.amplitude), w = harmonic_ ? f.omega : 0.0;
  const double speed = std::fabs(at(t).v) + b.B * W;
  const double C = std::fabs(f.k) * speed + std::fabs(f.c) * b.B + a * w;
  const double D = std::fabs(f.k) * b.B + std::fabs(f.c) * C + a * w * w;
  return {C * kBoundMargin, D * kBoundMargin, t + W};
}

std::optional<Contact> search_linear_contact(const LinearFlight& flight, double gap_a,
                                             double& certified, double& checked, double horizon,
                                             long& budget) {
  const LinearGap path{&flight, gap_a};
  while (certified <= horizon && budget > 0) {
    const AccelerationBound b = flight.acceleration_bound(certified);
    if (!(b.until > certified)) {  // a window below the resolution of t: no progress possible
      budget = 0;
      break;
    }
    if (auto contact = search_contact(path, b.B, certified, checked, horizon, budget, b.until))
      return contact;
    if (!(b.until < kInfinity)) break;
  }
  return std::nullopt;
}

}  // namespace impact
