// The per-step part of a run's summary (summary.hpp), for one particle (Real = double) or for a
// vector of particles (the ensemble, ensemble.hpp): the same operations in the same order for both,
// the branches taken as selections, so that every lane of the ensemble summarises its particle
// bit-identically to the single-particle observer. O(1) state: no trajectory is kept.
#pragma once

#include "impact/contact.hpp"

namespace impact {

template <class Real>
struct SummaryLanes {
  ContactCount<Real> contacts;  // contact.hpp's rule
  Real max_u{};                 // max over l of u^l, t_0 included
  Real first_l{};               // the first contact step l, -1 before there is one
  Real first_u{}, first_v{};    // the state at t_l before it, for the floor crossing
};

// The summary of a run that starts at u^0 = u0.
template <class Real>
void start_summary(SummaryLanes<Real>& s, const Real& u0) {
  s.max_u = u0;
  s.first_l = Real{} - 1;
}

// Step l from (u_before, v_before) at t_l to u^{l+1} = u with N^l = force.
template <class Real, class Step>
void summary_step(SummaryLanes<Real>& s, const Step& l, const Real& phi, const Real& u_before,
                  const Real& v_before, const Real& u, const Real& force) {
  decltype(u > u) contact;
  is_contact_step(phi, u, force, contact);
  count_contact(s.contacts, contact, l);
  const auto first = contact & (s.first_l < 0);
  s.first_l = first ? l : s.first_l;
  s.first_u = first ? u_before : s.first_u;
  s.first_v = first ? v_before : s.first_v;
  s.max_u = u > s.max_u ? u : s.max_u;
}

}  // namespace impact
