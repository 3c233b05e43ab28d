# Lemma 3 (Section 4): the a priori bounds, the energy inequality (4-6) and the impulse bound after
# (4-9), measured over a sweep of 144 runs of the direct scheme; and the same bounds with a
# time-dependent force f(t) = f + a sin(omega t + phase) under each reading of |f| (a PNG only:
# see plot.gp).
$(eval $(call driver_and_plot,lemma3,lemma3.png lemma3.svg lemma3_forcing.png))
