# Section 4 (existence proof): convergence of u_h as h -> 0, effective COR, identities (4-9), (4-10).
$(eval $(call driver_and_plot,convergence,convergence.png convergence.svg convergence_subsequences.png convergence_subsequences.svg))
