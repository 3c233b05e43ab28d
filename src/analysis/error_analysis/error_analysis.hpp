// experiments/error_analysis: the error analysis the paper announces (Section 6), checked. The
// campaign (error_campaign.hpp) runs every scheme on random scenes and checks every statement of
// paper_notes/error_analysis.md on each run; the sweeps (error_sweeps.hpp) draw each statement's
// error and bound against h (and against the number of impacts for Statement 3) on fixed scenes,
// and measure direct_located's order.
#pragma once

#include <toml++/toml.h>

#include "analysis/error_analysis/error_campaign.hpp"
#include "analysis/error_analysis/error_run.hpp"
#include "analysis/error_analysis/error_sweeps.hpp"
#include "analysis/experiment.hpp"

namespace impact::error_analysis {

struct ErrorAnalysisOptions {
  CampaignOptions campaign;
  bool sweeps = true;  // false: the campaign alone
  ErrorSweepOptions sweep;
};

// Writes campaign.csv (every check), checks.md (the summary table) and the sweeps' files to the
// results directory; returns the numbers of experiments/error_analysis/reference.toml.
toml::table run_error_analysis(const ExperimentContext& context,
                               const ErrorAnalysisOptions& options);
toml::table run_error_analysis(const ExperimentContext& context);

// The campaign's part of the summary: per check, runs, violations, median and worst ratio.
toml::table campaign_table(const CampaignResult& result);

extern const Experiment kErrorAnalysisExperiment;

}  // namespace impact::error_analysis
