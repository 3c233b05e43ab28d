#include "analysis/error_analysis/error_analysis.hpp"

#include <cstdio>
#include <sstream>
#include <string>

#include "analysis/error_analysis/error_sweeps.hpp"

namespace impact::error_analysis {
namespace {

// A check's name as a TOML key: "s3.direct.sup" -> "s3_direct_sup".
std::string key_of(std::string name) {
  for (char& c : name)
    if (c == '.') c = '_';
  return name;
}

std::string campaign_csv(const CampaignResult& result) {
  std::ostringstream out;
  out.precision(17);
  out << "check,scene,h,measured,bound,allowance,ratio,violated\n";
  for (const Check& c : result.checks) {
    if (c.name == "run.failed") continue;
    out << c.name << ',' << c.scene << ',' << c.h << ',' << c.measured << ',' << c.bound << ','
        << c.allowance << ',' << c.ratio() << ',' << c.violated() << '\n';
  }
  return out.str();
}

std::string checks_markdown(const CampaignResult& result) {
  std::ostringstream out;
  out << "| check | status | runs | violations | median ratio | worst ratio |\n"
      << "| --- | --- | --- | --- | --- | --- |\n";
  char buf[64];
  for (const CheckSummary& s : result.summaries) {
    const char* status = s.conjecture ? "conjecture" : s.identity ? "identity" : "bound";
    out << "| " << s.name << " | " << status << " | " << s.runs << " | " << s.violations << " | ";
    std::snprintf(buf, sizeof buf, "%.3g | %.3g |", s.median_ratio, s.worst_ratio);
    out << buf << '\n';
  }
  return out.str();
}

}  // namespace

toml::table campaign_table(const CampaignResult& result) {
  toml::table t{{"scenes", static_cast<std::int64_t>(result.scenes)},
                {"runs", static_cast<std::int64_t>(result.runs)},
                {"failed_runs", static_cast<std::int64_t>(result.failed_runs)}};
  std::int64_t violations = 0, conjecture_violations = 0;
  toml::table checks;
  for (const CheckSummary& s : result.summaries) {
    (s.conjecture ? conjecture_violations : violations) += static_cast<std::int64_t>(s.violations);
    checks.insert(key_of(s.name),
                  toml::table{{"conjecture", s.conjecture},
                              {"identity", s.identity},
                              {"runs", static_cast<std::int64_t>(s.runs)},
                              {"violations", static_cast<std::int64_t>(s.violations)},
                              {"median_ratio", s.median_ratio},
                              {"worst_ratio", s.worst_ratio}});
  }
  t.insert("violations", violations);
  t.insert("conjecture_violations", conjecture_violations);
  t.insert("checks", checks);
  return t;
}

toml::table run_error_analysis(const ExperimentContext& context,
                               const ErrorAnalysisOptions& options) {
  const CampaignResult campaign = run_campaign(options.campaign);
  context.write("campaign.csv", [&] { return campaign_csv(campaign); });
  context.write("checks.md", [&] { return checks_markdown(campaign); });
  toml::table summary{{"campaign", campaign_table(campaign)}};
  if (options.sweeps) summary.insert("sweeps", run_sweeps(context, options.sweep));
  return summary;
}

toml::table run_error_analysis(const ExperimentContext& context) {
  return run_error_analysis(context, ErrorAnalysisOptions{});
}

const Experiment kErrorAnalysisExperiment{
    "error_analysis",
    "the error analysis of the paper's future work (Section 6): bounds checked on random scenes",
    run_error_analysis};

}  // namespace impact::error_analysis
