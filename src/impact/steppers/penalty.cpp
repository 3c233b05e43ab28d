#include "impact/steppers/penalty.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <iterator>
#include <limits>
#include <new>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "impact/forces/force.hpp"
#include "impact/forces/gsl_errors.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/contact_law.hpp"

namespace impact {
namespace {

// Every odeiv2 stepper, by name. The implicit ones (rk1imp, rk2imp, rk4imp, bsimp, msbdf) use the
// Jacobian. GSL exports the types as pointer variables.
constexpr std::string_view kStepperNames[] = {"rk8pd",  "rkf45",  "rkck",    "rk4",
                                              "rk2",    "msbdf",  "msadams", "rk4imp",
                                              "rk2imp", "rk1imp", "bsimp"};
const gsl_odeiv2_step_type* const* const kStepperTypes[] = {
    &gsl_odeiv2_step_rk8pd,   &gsl_odeiv2_step_rkf45,  &gsl_odeiv2_step_rkck,
    &gsl_odeiv2_step_rk4,     &gsl_odeiv2_step_rk2,    &gsl_odeiv2_step_msbdf,
    &gsl_odeiv2_step_msadams, &gsl_odeiv2_step_rk4imp, &gsl_odeiv2_step_rk2imp,
    &gsl_odeiv2_step_rk1imp,  &gsl_odeiv2_step_bsimp};
static_assert(std::size(kStepperNames) == std::size(kStepperTypes));

const gsl_odeiv2_step_type* find_stepper(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kStepperNames); ++i)
    if (kStepperNames[i] == name) return *kStepperTypes[i];
  return nullptr;
}

// A bound on the ODE steps of one grid step, so that a tolerance the stepper cannot meet ends the
// run with converged = false instead of looping (practically) forever.
constexpr unsigned long kMaxOdeSteps = 1'000'000;
// The automatic budget of a whole run (PenaltyParams::max_ode_steps = 0): kMaxOdeSteps to start
// with, and this many more per grid step, so that free flight (about one ODE step per grid step)
// and resolved contacts never meet it while a run that needs 1e5 per step stops within seconds.
constexpr unsigned long kAutomaticStepsPerGridStep = 1000;

constexpr double kNever = std::numeric_limits<double>::infinity();

// The smallest tau > 0 with g + v tau + f tau^2 / 2 = 0, or +inf, from a gap g > 0 (or g = 0
// leaving the floor, v > 0): when free flight (the exact solution while N = 0) reaches the floor.
// Roots in the cancellation-free form.
double time_to_floor(double g, double v, double f) {
  const double a = 0.5 * f;
  if (a == 0.0) return v < 0.0 ? g / -v : kNever;
  const double disc = v * v - 4.0 * a * g;
  if (disc < 0.0) return kNever;
  const double q = -0.5 * (v + std::copysign(std::sqrt(disc), v));
  double tau = kNever;
  for (double r : {q / a, g / q})
    if (r > 0.0 && r < tau) tau = r;
  return tau;
}

// The tau >= 0 at which a particle in contact (g <= 0) leaves the floor, or +inf if it never
// does. In contact g'' = f - c_N g: an oscillation g = g_eq + R cos(w tau - theta) about
// g_eq = f / c_N, w = sqrt(c_N), which leaves the floor rising (sin(w tau - theta) < 0) at
// cos(w tau - theta) = -g_eq / R.
double time_to_exit(double g, double v, double f, double w) {
  const double g_eq = f / (w * w);
  const double A = g - g_eq, B = v / w;
  const double R = std::hypot(A, B);
  if (!(R > 0.0)) return kNever;  // at rest at g_eq <= 0
  const double c = -g_eq / R;
  if (c >= 1.0) return kNever;  // the oscillation stays below the floor (resting contact)
  if (c <= -1.0) return 0.0;    // it touches the floor only at its lowest point
  // The phase now is -theta: in (-pi, 0) while rising (v > 0), where the exit is still ahead; in
  // [-pi, 0] taken as [0, pi] while falling, which puts the exit a full turn later.
  double theta = std::atan2(B, A);
  if (v <= 0.0) theta = -std::fabs(theta);
  const double delta = theta - std::acos(c);
  return (v > 0.0 ? std::fmax(delta, 0.0) : delta + 2.0 * std::numbers::pi) / w;
}

struct DriverFree {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

}  // namespace

// The ODE is integrated in the gap g = u - phi rather than u, so that rtol measures the penetration
// and not the floor's distance from the origin: y = (g, v, P) with
//   g' = v,  v' = f(t) + N,  P' = N,  N = c_N max(-g, 0),
// where P, the impulse delivered since the last reset, gives N^l = (P(t_{l+1}) - P(t_l)) / h, the
// meaning of N^l in (4-1) (model.hpp). v - P - f t is a linear invariant, which every Runge-Kutta
// and linear multistep method keeps up to rounding, so h sum N^l = v^n - v^0 - f T holds to
// rounding whatever the tolerances (with f(t): v - P - int_0^t f, as long as the stepper
// integrates f(t) to its tolerance).
//
// The Impl lives on the heap and is never moved: gsl_odeiv2_system::params points to it and the
// driver points to `sys`, so moving a Penalty (its unique_ptr) keeps both pointers valid.
struct Penalty::Impl {
  Impl(const Model& model, const ContactLaw& law, double h, const PenaltyParams& params);
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  static int rhs(double t, const double y[], double dydt[], void* self);
  static int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self);
  double force_at(double t);
  double floor_time(double t, double g, double v);
  double exit_time(double t, double g, double v);

  double f;
  ForceFunction force;  // f(t)
  bool constant;        // f(t) = f
  // The first failure of an expression force (its message), which ends the run.
  std::string force_error;
  double phi;
  double h;
  double c_N;
  double w;     // sqrt(c_N): the contact oscillates at this angular frequency
  double tiny;  // a piece shorter than this is not worth splitting off: 1e-6 of a contact
  gsl_odeiv2_system sys;
  std::unique_ptr<gsl_odeiv2_driver, DriverFree> driver;
  std::array<double, 3> y{};
  bool contact_piece = false;  // the piece being integrated is a contact, for the Jacobian at g = 0
  // The last failed step, for failure_reason().
  std::string stepper_name;
  double rtol, atol;
  // The ODE steps taken since initialize(), at grid step l0, against the run's budget.
  std::int64_t max_ode_steps = 0;
  unsigned long run_steps = 0;
  std::int64_t l0 = 0;
  bool out_of_budget = false;
  int failure_status = GSL_SUCCESS;
  unsigned long failure_steps = 0;
  double failure_t = 0.0;
  std::array<double, 3> failure_y{};
};

Penalty::Impl::Impl(const Model& model, const ContactLaw& law, double grid_h,
                    const PenaltyParams& params)
    : f(model.f),
      force(model),
      constant(force.constant()),
      phi(model.phi),
      h(grid_h),
      // The compliance law (contact_law.hpp), which refuses a COR.
      c_N(std::get<ComplianceLaw>(law).stiffness) {
  if (!(h > 0.0) || !std::isfinite(h)) throw std::invalid_argument("Penalty: h must be > 0");
  if (!(c_N > 0.0) || !std::isfinite(c_N))
    throw std::invalid_argument("Penalty: stiffness c_N must be > 0 and finite");
  if (!(params.rtol > 0.0) || !(params.atol > 0.0))
    throw std::invalid_argument("Penalty: rtol and atol must be > 0");
  const gsl_odeiv2_step_type* type = find_stepper(params.stepper);
  if (!type) throw std::invalid_argument("Penalty: unknown GSL stepper \"" + params.stepper + "\"");
  stepper_name = params.stepper;
  if (params.max_ode_steps < 0)
    throw std::invalid_argument("Penalty: max_ode_steps must be >= 0 (0: automatic)");
  max_ode_steps = params.max_ode_steps;
  rtol = params.rtol;
  atol = params.atol;
  w = std::sqrt(c_N);
  const GslErrorsAsStatus errors_as_status;
  const double contact_time = std::numbers::pi / w;  // the duration of a contact when f = 0
  tiny = 1e-6 * contact_time;
  sys = gsl_odeiv2_system{&Impl::rhs, &Impl::jacobian, 3, this};
  // The first trial step resolves a contact; it grows by up to 5x per step in free flight.
  driver.reset(gsl_odeiv2_driver_alloc_y_new(&sys, type, std::min(h, contact_time / 16),
                                             params.atol, params.rtol));
  if (!driver) throw std::bad_alloc();
  gsl_odeiv2_driver_set_nmax(driver.get(), kMaxOdeSteps);
}

// f(t); an expression that is not finite where the stepper evaluates it records its message.
double Penalty::Impl::force_at(double t) {
  if (constant) return f;
  try {
    return force.at(t);
  } catch (const std::runtime_error& e) {
    if (force_error.empty()) force_error = e.what();
    return std::numeric_limits<double>::quiet_NaN();
  }
}

int Penalty::Impl::rhs(double t, const double y[], double dydt[], void* self) {
  Impl& m = *static_cast<Impl*>(self);
  // A non-finite stage (a step so large it overflowed) is a recoverable failure: GSL retries with
  // a smaller step. (The error control would let it through: GSL's max ignores NaN.)
  if (!std::isfinite(y[0]) || !std::isfinite(y[1])) return GSL_FAILURE;
  const double force = m.force_at(t);
  if (!m.force_error.empty()) return GSL_EBADFUNC;  // GSL stops at once
  const double N = m.c_N * std::fmax(-y[0], 0.0);
  dydt[0] = y[1];
  dydt[1] = force + N;
  dydt[2] = N;
  return GSL_SUCCESS;
}

// When the piece that starts at (t, g, v) ends: the particle reaches the floor (flying) or leaves
// it (in contact). For a constant force these are exact (time_to_floor, time_to_exit). For f(t),
// the floor is not reached before the first root of g + v tau - B tau^2 / 2 with B = sup |f|
// (ForceFunction::bound), so pieces that end there approach it from the free side, each leaving a
// gap O(tau^2) of the last (an expression has no bound: the force at t is frozen instead); the
// exit is estimated with f frozen at t, and a piece that ends early is followed by another.
double Penalty::Impl::floor_time(double t, double g, double v) {
  if (constant) return time_to_floor(g, v, f);
  const std::optional<double> bound = force.bound();
  return time_to_floor(g, v, bound ? -*bound : force_at(t));
}

double Penalty::Impl::exit_time(double t, double g, double v) {
  return time_to_exit(g, v, constant ? f : force_at(t), w);
}

// The exact Jacobian (msbdf and the implicit Runge-Kutta steppers need it): dN/dg = -c_N in
// contact, 0 off it; at g = 0 exactly, the one-sided derivative of the piece being integrated.
// df/dt by a central difference (step cbrt(eps) max(1, |t|): error O(eps^(2/3)) relative, enough
// for the Newton iterations of an implicit stepper).
int Penalty::Impl::jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self) {
  Impl& m = *static_cast<Impl*>(self);
  const bool contact = y[0] < 0.0 || (y[0] == 0.0 && m.contact_piece);
  const double dN = contact ? -m.c_N : 0.0;
  const double J[9] = {0.0, 1.0, 0.0,   // g' = v
                       dN,  0.0, 0.0,   // v' = f + N
                       dN,  0.0, 0.0};  // P' = N
  std::copy(J, J + 9, dfdy);
  std::fill(dfdt, dfdt + 3, 0.0);
  if (!m.constant) {
    const double d = 6.055454452393343e-06 * std::fmax(1.0, std::fabs(t));  // cbrt(eps)
    dfdt[1] = (m.force_at(t + d) - m.force_at(t - d)) / (2 * d);
    if (!m.force_error.empty()) return GSL_EBADFUNC;
  }
  return GSL_SUCCESS;
}

std::span<const std::string_view> penalty_stepper_names() {
  return kStepperNames;
}

Penalty::Penalty(const Model& model, double h, const PenaltyParams& params)
    : Penalty(model, contact_law(model, MethodParams(params)), h, params) {}
Penalty::Penalty(const Model& model, const ContactLaw& law, double h, const PenaltyParams& params)
    : impl_(std::make_unique<Impl>(model, law, h, params)) {}
Penalty::Penalty(Penalty&&) noexcept = default;
Penalty& Penalty::operator=(Penalty&&) noexcept = default;
Penalty::~Penalty() = default;

// One grid step, t_l = l h to t_{l+1} = (l+1) h, both computed from l (never accumulated).
//
// Driver state: the adapted step size (and a multistep method's history) is kept from one grid
// step to the next; that is what makes free flight cost about one ODE step per grid step. Only
// initialize() resets the driver: msbdf and msadams ignore the y they are given once started.
//
// Pieces: the right-hand side is only Lipschitz where the particle reaches or leaves the floor
// (N has a kink there). A step that straddles a kink loses the stepper's order while its error
// estimate may not notice (with a grid point inside the contact, rk4imp and bsimp ended 5-6 digits
// short of their tolerance), and an adaptive step in free flight can jump over a whole contact,
// pi/sqrt(c_N) long, with no stage landing in it: the particle then goes through the floor. Both
// instants are known in closed form from the state, since each phase is linear: a parabola off the
// floor (time_to_floor), a harmonic oscillation in contact (time_to_exit). So a grid step is
// integrated in smooth pieces that end at them. The driver is reset at each kink, so that a
// multistep method does not extrapolate its history across it; the step size d->h is kept.
//
// iterations = the ODE steps GSL accepted (driver->n summed over the pieces), not counting
// rejected trial steps. A failure (more than kMaxOdeSteps steps, a tolerance GSL cannot meet, a
// non-finite state) gives converged = false and leaves s at its t_l value (finite if it was).
//
// Compliance is its own impact law, elastic: the constructor refuses a COR (contact_law.hpp).
void Penalty::initialize(const State& s, std::int64_t l) {
  Impl& m = *impl_;
  gsl_odeiv2_driver_reset(m.driver.get());
  m.y = {s.u - m.phi, s.v, 0.0};
  m.force_error.clear();
  m.run_steps = 0;
  m.l0 = l;
}

StepInfo Penalty::do_step(State& s, std::int64_t l) {
  Impl& m = *impl_;
  gsl_odeiv2_driver* d = m.driver.get();
  // GSL's default handler would abort the process (e.g. on "step size too small"); every status
  // is checked here instead.
  const GslErrorsAsStatus errors_as_status;
  const double P0 = m.y[2];
  double t = static_cast<double>(l) * m.h;
  const double t_end = static_cast<double>(l + 1) * m.h;

  StepInfo info;
  unsigned long taken = 0;
  int status = GSL_SUCCESS;
  // This grid step may take kMaxOdeSteps, and no more than what is left of the run's budget.
  const unsigned long budget =
      m.max_ode_steps > 0
          ? static_cast<unsigned long>(m.max_ode_steps)
          : kMaxOdeSteps + kAutomaticStepsPerGridStep * static_cast<unsigned long>(l + 1 - m.l0);
  const unsigned long left = budget > m.run_steps ? budget - m.run_steps : 0;
  const unsigned long limit = std::min(kMaxOdeSteps, left);
  m.out_of_budget = false;
  while (t < t_end) {
    const double g = m.y[0], v = m.y[1];
    bool flying = g > 0.0 || (g == 0.0 && v > 0.0);
    double tau = flying ? m.floor_time(t, g, v) : m.exit_time(t, g, v);
    if (tau < m.tiny) {  // at a kink already (up to rounding): the next piece is the other phase
      flying = !flying;
      tau = flying ? m.floor_time(t, 0.0, v) : m.exit_time(t, 0.0, v);
    }
    m.contact_piece = !flying;
    const bool to_kink = tau < t_end - t;
    double target = to_kink ? t + std::fmax(tau, m.tiny) : t_end;
    if (!(target > t)) target = t_end;  // t so large that the piece is below its resolution
    if (taken >= limit) {
      status = GSL_EMAXITER;
      break;
    }
    gsl_odeiv2_driver_set_nmax(d, limit - taken);
    status = gsl_odeiv2_driver_apply(d, &t, target, m.y.data());
    // On GSL_EMAXITER the driver has taken one step more than its count says.
    taken += d->n + (status == GSL_EMAXITER ? 1 : 0);
    if (status != GSL_SUCCESS) break;
    if (to_kink) gsl_odeiv2_driver_reset(d);
  }
  info.iterations = static_cast<int>(std::min<unsigned long>(taken, INT_MAX));
  m.run_steps += taken;
  m.out_of_budget = status == GSL_EMAXITER && limit < kMaxOdeSteps;
  if (status != GSL_SUCCESS ||
      !(std::isfinite(m.y[0]) && std::isfinite(m.y[1]) && std::isfinite(m.y[2]))) {
    info.converged = false;
    m.failure_status = status;
    m.failure_steps = taken;
    m.failure_t = t;
    m.failure_y = m.y;
    return info;
  }
  info.contact_force = (m.y[2] - P0) / m.h;
  s.u = m.y[0] + m.phi;
  s.v = m.y[1];
  return info;
}

std::string Penalty::failure_reason() const {
  const Impl& m = *impl_;
  std::ostringstream msg;
  msg.precision(3);
  msg << "GSL odeiv2 stepper " << m.stepper_name << " ";
  if (!m.force_error.empty())
    msg << "stopped: " << m.force_error;
  else if (m.out_of_budget)
    msg << "used up the run's budget of ODE steps (" << m.run_steps
        << " since the start; method.max_ode_steps, automatic: " << kMaxOdeSteps << " + "
        << kAutomaticStepsPerGridStep << " per grid step)";
  else if (m.failure_status == GSL_EMAXITER)
    msg << "took more than " << kMaxOdeSteps << " ODE steps in this grid step";
  else if (m.failure_status != GSL_SUCCESS)
    msg << "could not meet rtol = " << m.rtol << ", atol = " << m.atol
        << " (GSL: " << gsl_strerror(m.failure_status) << ") after " << m.failure_steps
        << " ODE steps";
  else
    msg << "produced a non-finite state after " << m.failure_steps << " ODE steps";
  msg << ", at t = " << m.failure_t << " with u - phi = " << m.failure_y[0]
      << ", v = " << m.failure_y[1] << " (c_N = " << m.c_N
      << ": contacts last pi/sqrt(c_N) = " << std::numbers::pi / m.w << ")";
  return msg.str();
}

}  // namespace impact
