# Section 4 (existence proof): convergence of u_h as h -> 0, effective COR, identities (4-9), (4-10).
EXPERIMENTS += convergence
convergence_DRIVER := $(BUILD)/experiments/convergence/exp_convergence
convergence_OUTPUTS := figures/convergence.png figures/convergence.svg \
  figures/convergence_subsequences.png figures/convergence_subsequences.svg \
  $(RESULTS)/convergence/summary.toml
$(convergence_OUTPUTS) &: experiments/convergence/plot.gp $(convergence_DRIVER)
	@mkdir -p $(RESULTS)/convergence figures
	$(convergence_DRIVER) $(RESULTS)/convergence
	gnuplot -e "results='$(RESULTS)/convergence'" experiments/convergence/plot.gp
