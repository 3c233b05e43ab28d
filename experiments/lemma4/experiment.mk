# Lemma 4 (uniqueness) and its proof (4-11)-(4-13): paths under COR = 1, weak solutions, (4-12).
$(eval $(call driver_and_plot,lemma4,lemma4.png lemma4.svg))
