# Figure 2 (Section 5.1): the spline approximation S_eps, from the paper's formulas and GSL.
EXPERIMENTS += figure2
figure2_DRIVER := $(BUILD)/experiments/figure2/exp_figure2
figure2_OUTPUTS := figures/figure2.png figures/figure2.svg $(RESULTS)/figure2/summary.toml
$(figure2_OUTPUTS) &: experiments/figure2/plot.gp $(figure2_DRIVER)
	@mkdir -p $(RESULTS)/figure2 figures
	$(figure2_DRIVER) $(RESULTS)/figure2
	gnuplot -e "results='$(RESULTS)/figure2'" experiments/figure2/plot.gp
