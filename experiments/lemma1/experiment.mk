# Lemma 1 (Section 3): the Laplace-transform energy check, on the exact solution and on the direct
# scheme with the scenes of Figures 3 and 4 (which it reads, so they are prerequisites).
EXPERIMENTS += lemma1
lemma1_DRIVER := $(BUILD)/experiments/lemma1/exp_lemma1
lemma1_SCENES := experiments/figure3/no_cor.toml experiments/figure3/cor075.toml \
                 experiments/figure4/no_cor.toml experiments/figure4/cor075.toml
lemma1_OUTPUTS := figures/lemma1.png figures/lemma1.svg $(RESULTS)/lemma1/summary.toml
$(lemma1_OUTPUTS) &: experiments/lemma1/plot.gp $(lemma1_DRIVER) $(lemma1_SCENES)
	@mkdir -p $(RESULTS)/lemma1 figures
	$(lemma1_DRIVER) $(RESULTS)/lemma1
	gnuplot -e "results='$(RESULTS)/lemma1'" experiments/lemma1/plot.gp
