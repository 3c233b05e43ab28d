# Work against precision: every method's error against the reference and the CPU time of its
# solve, over 4 decades of h (or 8 of tolerance), on the paper's Figure 3 and 4 scenes, an
# off-grid one, the vibrating table with f(t) (period 1, chaotic) and an expression force;
# Siconos's Moreau-Jean and LSODAR too when it is installed (libsiconos-kernel-dev).
# Every figure has CPU times on its x axis, so all go to $(TIMING_DIR) (see the Makefile).
EXPERIMENTS += work_precision
work_precision_DRIVER := $(BUILD)/experiments/work_precision/exp_work_precision
work_precision_SCENES := experiments/figure3/no_cor.toml experiments/figure3/cor075.toml \
  experiments/figure4/no_cor.toml experiments/figure4/cor075.toml \
  experiments/work_precision/offgrid.toml experiments/work_precision/table_period1.toml \
  experiments/work_precision/table_chaotic.toml experiments/work_precision/expression.toml
work_precision_FIGURES := $(foreach f,work_precision $(addprefix work_precision_,figure3_no_cor \
  figure3_cor075 figure4_no_cor figure4_cor075 offgrid_no_cor forced table_period1 \
  table_chaotic expression located),$(f).png $(f).svg)
TIMING_FIGURES += $(work_precision_FIGURES)
work_precision_OUTPUTS := $(addprefix $(TIMING_DIR)/,$(work_precision_FIGURES)) \
  $(RESULTS)/work_precision/summary.toml $(RESULTS)/work_precision/orders.md
$(work_precision_OUTPUTS) &: experiments/work_precision/plot.gp $(work_precision_SCENES) \
    $(work_precision_DRIVER)
	@mkdir -p $(RESULTS)/work_precision $(TIMING_DIR)
	$(work_precision_DRIVER) $(RESULTS)/work_precision
	gnuplot -e "results='$(RESULTS)/work_precision'; out='$(TIMING_DIR)'" \
	  experiments/work_precision/plot.gp
