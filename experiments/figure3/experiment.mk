# Figure 3 (Section 5.2, f = 0): u, v, N, E without COR and with COR = 0.75, direct and fb_newton
# against the exact solution; plus the energy kept by the impact over an h sweep.
EXPERIMENTS += figure3
figure3_DRIVER := $(BUILD)/experiments/figure3/exp_figure3
figure3_SCENES := experiments/figure3/no_cor.toml experiments/figure3/cor075.toml
figure3_OUTPUTS := figures/figure3.png figures/figure3.pdf figures/figure3_h_sweep.png \
    figures/figure3_h_sweep.svg $(RESULTS)/figure3/summary.toml
$(figure3_OUTPUTS) &: experiments/figure3/plot.gp $(figure3_SCENES) $(IMPACT) $(figure3_DRIVER)
	@mkdir -p $(RESULTS)/figure3 figures
	for scene in no_cor cor075; do for method in direct fb_newton exact; do \
	  channels='["u","v","N_scheme","E"]'; [ $$method = exact ] && channels='["u","v","N","E"]'; \
	  $(IMPACT) run experiments/figure3/$$scene.toml --set method.name=$$method --quiet \
	    --set "output.channels=$$channels" \
	    --out $(RESULTS)/figure3/$${scene}_$$method.csv || exit 1; done; done
	$(figure3_DRIVER) $(RESULTS)/figure3
	gnuplot -e "results='$(RESULTS)/figure3'" experiments/figure3/plot.gp
	$(call FIX_PDF_DATE,figures/figure3.pdf)
