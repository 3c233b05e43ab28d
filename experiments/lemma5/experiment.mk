# Lemma 5 (Section 5.1): N_eps = S''/6 paired with test functions, by GSL quadrature.
EXPERIMENTS += lemma5
lemma5_DRIVER := $(BUILD)/experiments/lemma5/exp_lemma5
lemma5_OUTPUTS := figures/lemma5.png figures/lemma5.svg $(RESULTS)/lemma5/summary.toml
$(lemma5_OUTPUTS) &: experiments/lemma5/plot.gp $(lemma5_DRIVER)
	@mkdir -p $(RESULTS)/lemma5 figures
	$(lemma5_DRIVER) $(RESULTS)/lemma5
	gnuplot -e "results='$(RESULTS)/lemma5'" experiments/lemma5/plot.gp
