// The per-step part of a run's summary (summary.hpp), for one particle (Real = double) or for a
// vector of particles (the ensemble, ensemble.hpp): the same operations in the same order for both,
// the branches taken as selections, so that every lane of the ensemble summarises its particle
// bit-identically to the single-particle observer. O(1) state: no trajectory is kept.
#pragma once

#include "impact/model/contact.hpp"

namespace impact {

template <class Real>
struct SummaryLanes {
  ContactCount<Real> contacts;  // contact.hpp's rule
  Real max_u{};                 // max over l of u^l, t_0 included
  // The first contact step l and the state at t_l before it (for the floor crossing), once
  // contacts.episodes > 0.
  Real first_l{}, first_u{}, first_v{};
};

// The summary of a run that starts at u^0 = u0.
template <class Real>
void start_summary(SummaryLanes<Real>& s, const Real& u0) {
  s.max_u = u0;
}

// Step l from (u_before, v_before) at t_l to u^{l+1} = u with N^l = force. Each selection is on
// one comparison: combining masks (`a & b`) or nesting selections made GCC build the AVX-512 masks
// lane by lane (10x slower). CaptureFirst = false leaves out the first contact's capture, which
// changes nothing once every lane's first episode has started (the ensemble's steps after that).
template <bool CaptureFirst = true, class Real, class Step>
void summary_step(SummaryLanes<Real>& s, const Step& l, const Real& phi, const Real& u_before,
                  const Real& v_before, const Real& u, const Real& force) {
  // Until the first contact episode starts every step is noted; the last one noted is its first.
  if constexpr (CaptureFirst) {
    const auto none_yet = s.contacts.episodes == 0;
    s.first_l = none_yet ? l : s.first_l;
    s.first_u = none_yet ? u_before : s.first_u;
    s.first_v = none_yet ? v_before : s.first_v;
  }
  decltype(u > u) contact;
  is_contact_step(phi, u, force, contact);
  count_contact(s.contacts, contact);
  s.max_u = u > s.max_u ? u : s.max_u;
}

}  // namespace impact
