# Work against precision: every method's error against `exact` and the CPU time of its
# solve, over 4 decades of h (or 8 of tolerance), on the paper's Figure 3 and 4 scenes and an
# off-grid one; Siconos's Moreau-Jean too when it is installed (libsiconos-kernel-dev).
EXPERIMENTS += work_precision
work_precision_DRIVER := $(BUILD)/experiments/work_precision/exp_work_precision
work_precision_SCENES := experiments/figure3/no_cor.toml experiments/figure3/cor075.toml \
  experiments/figure4/no_cor.toml experiments/figure4/cor075.toml \
  experiments/work_precision/offgrid.toml
work_precision_FIGURES := figures/work_precision $(addprefix figures/work_precision_,\
  figure3_no_cor figure3_cor075 figure4_no_cor figure4_cor075 offgrid_no_cor)
work_precision_OUTPUTS := $(addsuffix .png,$(work_precision_FIGURES)) \
  $(addsuffix .svg,$(work_precision_FIGURES)) $(RESULTS)/work_precision/summary.toml \
  $(RESULTS)/work_precision/orders.md
$(work_precision_OUTPUTS) &: experiments/work_precision/plot.gp $(work_precision_SCENES) \
    $(work_precision_DRIVER)
	@mkdir -p $(RESULTS)/work_precision figures
	$(work_precision_DRIVER) $(RESULTS)/work_precision
	gnuplot -e "results='$(RESULTS)/work_precision'" experiments/work_precision/plot.gp
