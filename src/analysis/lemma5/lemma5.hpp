// Lemma 5 (Section 5.1): N_eps = S''/6 (the proof's contact force) and S''/3 paired with smooth
// test functions psi for eps = 1e-1 ... 1e-6 (half decades) by GSL quadrature over the two cubic
// pieces (spline_contact.hpp), against psi(t*), the limit the lemma claims.
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::lemma5 {

// Returns {lemma5 = {...}}: the masses of S''/6 and S''/3 at Figure 2's eps, the ratios at each
// decade of eps and the fitted convergence slope per psi (the keys of
// experiments/lemma5/reference.toml). Writes pairing_<psi>.csv: eps, <N_eps, psi>/psi(t*),
// <S''/3, psi>/psi(t*), the deviation from 1/2, its leading term psi''(t*) eps^2 / (24 psi(t*)),
// and each piece's share.
toml::table run_lemma5(const ExperimentContext& context);

extern const Experiment kLemma5Experiment;

}  // namespace impact::lemma5
