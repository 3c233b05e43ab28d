// The Lemma 3 experiment's part for a time-dependent body force (lemma3_forcing.hpp): its key
// numbers under [lemma3_forcing] and forcing_runs.csv, one row per run (what plot.gp draws in
// figures/lemma3_forcing).
#pragma once

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "analysis/lemma3/lemma3_forcing.hpp"

namespace impact::lemma3 {

// [lemma3_forcing]: over all runs, per reading, the violations of the velocity bound and of both
// displacement bounds, their median and largest ratio and the case of the largest; the proof's
// bound P; the energy counts; per method the violation counts.
toml::table forcing_summary(const std::vector<ForcingRun>& runs);

std::string forcing_runs_csv(const std::vector<ForcingRun>& runs);

}  // namespace impact::lemma3
