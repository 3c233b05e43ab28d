# The paper's future work (Section 6): the error analysis of its schemes (paper_notes/error_analysis.md),
# checked by a campaign of random scenes, with one figure per statement and direct_located.
$(eval $(call driver_and_plot,error_analysis,$(foreach f,flight impact zeno no_cor located,error_analysis_$(f).png error_analysis_$(f).svg) error_analysis_campaign.png,experiments/error_analysis/flight.toml experiments/figure4/cor075.toml experiments/figure3/no_cor.toml experiments/figure3/cor075.toml experiments/work_precision/offgrid.toml experiments/work_precision/table_period1.toml))
