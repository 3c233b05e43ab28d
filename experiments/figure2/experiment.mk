# Figure 2 (Section 5.1): the spline approximation S_eps, from the paper's formulas and GSL.
$(eval $(call driver_and_plot,figure2,figure2.png figure2.svg))
