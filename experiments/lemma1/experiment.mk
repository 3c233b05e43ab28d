# Lemma 1 (Section 3): the Laplace-transform energy check, on the exact solution and on the direct
# scheme with the scenes of Figures 3 and 4 (which it reads, so they are prerequisites).
lemma1_SCENES := experiments/figure3/no_cor.toml experiments/figure3/cor075.toml \
                 experiments/figure4/no_cor.toml experiments/figure4/cor075.toml
$(eval $(call driver_and_plot,lemma1,lemma1.png lemma1.svg,$(lemma1_SCENES)))
