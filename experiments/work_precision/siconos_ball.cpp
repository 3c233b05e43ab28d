#include "siconos_ball.hpp"

#include <SiconosKernel.hpp>
#include <stdexcept>

namespace impact {

struct SiconosBall::Impl {
  SP::LagrangianLinearTIDS ball;
  SP::TimeStepping simulation;
  SP::SiconosVector q, v, p;
  double h;
  bool started = false;
};

SiconosBall::SiconosBall(const Model& model, const State& initial, double h, std::int64_t steps)
    : impl_(std::make_shared<Impl>()) {
  SP::SiconosVector q0(new SiconosVector(1)), v0(new SiconosVector(1));
  (*q0)(0) = initial.u;
  (*v0)(0) = initial.v;
  SP::SiconosMatrix mass(new SimpleMatrix(1, 1));
  (*mass)(0, 0) = 1.0;
  impl_->ball.reset(new LagrangianLinearTIDS(q0, v0, mass));
  SP::SiconosVector force(new SiconosVector(1));
  (*force)(0) = model.f;
  impl_->ball->setFExtPtr(force);

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

  SP::MoreauJeanOSI integrator(new MoreauJeanOSI(0.5));
  SP::TimeDiscretisation grid(new TimeDiscretisation(0.0, h));
  SP::OneStepNSProblem lcp(new LCP());
  impl_->simulation.reset(new TimeStepping(system, grid, integrator, lcp));
  impl_->simulation->initialize();
  impl_->q = impl_->ball->q();
  impl_->v = impl_->ball->velocity();
  impl_->p = impl_->ball->p(1);
  impl_->h = h;
}

void SiconosBall::initialize(const State&, std::int64_t l) {
  if (l != 0 || impl_->started)
    throw std::logic_error("SiconosBall: a simulation runs once, from the state it was built with");
}

StepInfo SiconosBall::do_step(State& s, std::int64_t) {
  Impl& m = *impl_;
  m.started = true;
  m.simulation->computeOneStep();
  s.u = (*m.q)(0);
  s.v = (*m.v)(0);
  StepInfo info;
  info.contact_force = (*m.p)(0) / m.h;
  m.simulation->nextStep();
  return info;
}

}  // namespace impact
