// The campaign's run (error_campaign.hpp): every scheme on every scene against the exact solution,
// and every check of error_checks.hpp that applies, summarised per check.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/error_analysis/error_campaign.hpp"
#include "analysis/error_analysis/error_checks.hpp"

namespace impact::error_analysis {

// The exact solution and every scheme on the scene.
SceneRuns run_scene_runs(const CampaignScene& scene, std::size_t index);

// The checks of one scene (all schemes), appended to `out`.
void check_scene(const CampaignScene& scene, std::size_t index, std::vector<Check>& out);

CampaignResult run_campaign(const CampaignOptions& options);

}  // namespace impact::error_analysis
