#include "analysis/lemma4/energy_identity.hpp"

namespace impact::lemma4 {

EnergyIdentity412 energy_identity_412(const ExactSolution& u, const ExactSolution& w,
                                      const Model& model, double t) {
  const State u0 = u.at(0), w0 = w.at(0), ut = u.at(t), wt = w.at(t);
  EnergyIdentity412 r;
  const double z0 = u0.v - w0.v, zt = ut.v - wt.v;
  r.lhs = (zt * zt - z0 * z0) / 2;
  r.paper_rhs = -ut.v * wt.v + u0.v * w0.v;
  r.force_terms = model.f * (ut.u - u0.u + wt.u - w0.u);
  r.dropped_n1_u = energy(model, ut) - energy(model, u0);
  r.dropped_n2_w = energy(model, wt) - energy(model, w0);
  r.paper_413 = zt * zt - z0 * z0;
  return r;
}

}  // namespace impact::lemma4
