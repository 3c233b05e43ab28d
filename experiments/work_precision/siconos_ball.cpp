#include "siconos_ball.hpp"

#include <SiconosKernel.hpp>
#include <cmath>
#include <stdexcept>

#include "impact/forces/force.hpp"

namespace impact {
namespace {

// The particle with the project's body force: Siconos asks computeFExt(t) for f(t) wherever its
// integrator needs it (both ends of a Moreau-Jean step, every right-hand side LSODAR evaluates).
class ForcedBall : public LagrangianLinearTIDS {
 public:
  ForcedBall(SP::SiconosVector q0, SP::SiconosVector v0, SP::SiconosMatrix mass, const Model& model)
      : LagrangianLinearTIDS(q0, v0, mass), force_(model) {
    _fExt.reset(new SiconosVector(1));
    _hasConstantFExt = false;
    computeFExt(0.0);
  }
  void computeFExt(double time) override { (*_fExt)(0) = force_.at(time); }
  const ForceFunction& force() const { return force_; }

 private:
  ForceFunction force_;
};

// Two events closer than this (s) are one for Siconos's event manager (its time ticks).
constexpr double kSameEvent = 1e-12;

}  // namespace

struct SiconosBall::Impl {
  std::shared_ptr<ForcedBall> ball;
  SP::TimeStepping time_stepping;  // one of the two is set
  SP::EventDriven event_driven;
  SP::SiconosVector q, v, p;
  double phi = 0, h = 0;
  bool started = false;
};

SiconosBall::SiconosBall(const Model& model, const State& initial, double h, std::int64_t steps,
                         SiconosIntegrator integrator, double tolerance)
    : impl_(std::make_shared<Impl>()) {
  SP::SiconosVector q0(new SiconosVector(1)), v0(new SiconosVector(1));
  (*q0)(0) = initial.u;
  (*v0)(0) = initial.v;
  SP::SiconosMatrix mass(new SimpleMatrix(1, 1));
  (*mass)(0, 0) = 1.0;
  impl_->ball = std::make_shared<ForcedBall>(q0, v0, mass, model);

  // y = H u + b = u - phi >= 0, with Newton's impact law v+ = -e v-.
  SP::SimpleMatrix H(new SimpleMatrix(1, 1));
  (*H)(0, 0) = 1.0;
  SP::SiconosVector b(new SiconosVector(1));
  (*b)(0) = -model.phi;
  SP::NonSmoothLaw law(new NewtonImpactNSL(model.cor ? *model.cor : 1.0));
  SP::Relation relation(new LagrangianLinearTIR(H, b));
  SP::Interaction contact(new Interaction(law, relation));

  SP::NonSmoothDynamicalSystem system(
      new NonSmoothDynamicalSystem(0.0, static_cast<double>(steps) * h));
  system->insertDynamicalSystem(impl_->ball);
  system->link(contact, impl_->ball);

  SP::TimeDiscretisation grid(new TimeDiscretisation(0.0, h));
  if (integrator == SiconosIntegrator::moreau_jean) {
    SP::MoreauJeanOSI osi(new MoreauJeanOSI(0.5));
    SP::OneStepNSProblem lcp(new LCP());
    impl_->time_stepping.reset(new TimeStepping(system, grid, osi, lcp));
    impl_->time_stepping->initialize();
  } else {
    SP::LsodarOSI osi(new LsodarOSI());
    osi->setTol(1, tolerance, tolerance);
    impl_->event_driven.reset(new EventDriven(system, grid));
    impl_->event_driven->associate(osi, impl_->ball);
    SP::OneStepNSProblem impact(new LCP()), acceleration(new LCP());
    impl_->event_driven->insertNonSmoothProblem(impact, SICONOS_OSNSP_ED_IMPACT);
    impl_->event_driven->insertNonSmoothProblem(acceleration, SICONOS_OSNSP_ED_SMOOTH_ACC);
    impl_->event_driven->initialize();
  }
  impl_->q = impl_->ball->q();
  impl_->v = impl_->ball->velocity();
  impl_->p = impl_->ball->p(1);
  impl_->phi = model.phi;
  impl_->h = h;
}

void SiconosBall::initialize(const State&, std::int64_t l) {
  if (l != 0 || impl_->started)
    throw std::logic_error("SiconosBall: a simulation runs once, from the state it was built with");
}

StepInfo SiconosBall::do_step(State& s, std::int64_t l) {
  Impl& m = *impl_;
  m.started = true;
  StepInfo info;
  if (m.time_stepping) {
    m.time_stepping->computeOneStep();
    s.u = (*m.q)(0);
    s.v = (*m.v)(0);
    info.contact_force = (*m.p)(0) / m.h;
    m.time_stepping->nextStep();
    return info;
  }
  // Event-driven: process events up to t_{l+1}, the grid event. Siconos drops a grid event that
  // falls within its tick of an impact, so the step also ends at the last event before t_{l+1}
  // when the next one lies beyond it.
  const double t0 = static_cast<double>(l) * m.h, t1 = static_cast<double>(l + 1) * m.h;
  const State before = s;
  const SP::EventsManager events = m.event_driven->eventsManager();
  bool impact = false;
  while (events->hasNextEvent() && events->startingTime() < t1 - kSameEvent) {
    if (events->nextTime() > t1 + kSameEvent && events->startingTime() > t0) break;
    m.event_driven->advanceToEvent();
    impact = impact || events->nextEvent()->getType() == NS_EVENT;
    m.event_driven->processEvents();
  }
  s.u = (*m.q)(0);
  s.v = (*m.v)(0);
  // In contact at the end of the step: on the floor to LSODAR's accuracy and not leaving it.
  const bool resting = s.u - m.phi <= 1e-9 && std::fabs(s.v) <= 1e-9;
  if (impact || resting) {
    const double impulse = s.v - before.v - m.ball->force().integral(t0, t1);
    info.contact_force = std::fmax(0.0, impulse) / m.h;
  }
  return info;
}

}  // namespace impact
