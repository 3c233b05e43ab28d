# Lemma 5 (Section 5.1): N_eps = S''/6 paired with test functions, by GSL quadrature.
$(eval $(call driver_and_plot,lemma5,lemma5.png lemma5.svg))
