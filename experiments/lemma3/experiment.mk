# Lemma 3 (Section 4): the a priori bounds, the energy inequality (4-6) and the impulse bound after
# (4-9), measured over a sweep of 144 runs of the direct scheme.
EXPERIMENTS += lemma3
lemma3_DRIVER := $(BUILD)/experiments/lemma3/exp_lemma3
lemma3_OUTPUTS := figures/lemma3.png figures/lemma3.svg $(RESULTS)/lemma3/summary.toml
$(lemma3_OUTPUTS) &: experiments/lemma3/plot.gp $(lemma3_DRIVER)
	@mkdir -p $(RESULTS)/lemma3 figures
	$(lemma3_DRIVER) $(RESULTS)/lemma3
	gnuplot -e "results='$(RESULTS)/lemma3'" experiments/lemma3/plot.gp
