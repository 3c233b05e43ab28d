// Lemma 3 (Section 4), the experiment: the a priori bounds on max|v^l| and max|u^l|, the energy
// inequality E^{l+1} <= E^l (4-6) and the bound on h sum N^l after (4-9), measured on the 144 runs
// of lemma3_sweep() (bounds.hpp: direct scheme, no COR, phi = 0, T = 2).
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::lemma3 {

// The key numbers of the sweep (summarize_lemma3) under [lemma3], and runs.csv: one row per run
// with its data, measured maxima, bounds, ratios and energy counts (what plot.gp draws).
toml::table run_lemma3(const ExperimentContext& context);

extern const Experiment kLemma3Experiment;

}  // namespace impact::lemma3
