# Numerical stability on stiff and extreme cases: every method over h = 1e-9..1 on the
# extreme cases, fb_newton over its smoothing parameter, penalty over c_N and its GSL steppers.
# The tables of the extreme cases go to $(RESULTS)/stability/table.md.
EXPERIMENTS += stability
stability_DRIVER := $(BUILD)/experiments/stability/exp_stability
stability_OUTPUTS := figures/stability_map.png figures/stability_map.svg \
    figures/stability_params.png figures/stability_params.svg figures/stability_stiff.png \
    figures/stability_stiff.svg $(RESULTS)/stability/summary.toml
$(stability_OUTPUTS) &: experiments/stability/plot.gp $(stability_DRIVER)
	@mkdir -p $(RESULTS)/stability figures
	$(stability_DRIVER) $(RESULTS)/stability
	gnuplot -e "results='$(RESULTS)/stability'" experiments/stability/plot.gp
