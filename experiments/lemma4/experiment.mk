# Lemma 4 (uniqueness) and its proof (4-11)-(4-13): paths under COR = 1, weak solutions, (4-12).
EXPERIMENTS += lemma4
lemma4_DRIVER := $(BUILD)/experiments/lemma4/exp_lemma4
lemma4_OUTPUTS := figures/lemma4.png figures/lemma4.svg $(RESULTS)/lemma4/summary.toml
$(lemma4_OUTPUTS) &: experiments/lemma4/plot.gp $(lemma4_DRIVER)
	@mkdir -p $(RESULTS)/lemma4 figures
	$(lemma4_DRIVER) $(RESULTS)/lemma4
	gnuplot -e "results='$(RESULTS)/lemma4'" experiments/lemma4/plot.gp
