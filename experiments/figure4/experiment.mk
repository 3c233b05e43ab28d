# Figure 4 (Section 5.2, f = -9.80665): u, v, N, E without COR and with COR = 0.75, direct and
# fb_newton against the exact solution; plus rest time and energy loss over an h sweep, and the
# readings figure: (5-1) in closed form vs as printed, and the energy change of a contact step.
EXPERIMENTS += figure4
figure4_DRIVER := $(BUILD)/experiments/figure4/exp_figure4
figure4_SCENES := experiments/figure4/no_cor.toml experiments/figure4/cor075.toml
figure4_OUTPUTS := figures/figure4.png figures/figure4.pdf figures/figure4_h_sweep.png \
    figures/figure4_h_sweep.svg figures/figure4_readings.png figures/figure4_readings.svg \
    $(RESULTS)/figure4/summary.toml $(RESULTS)/figure4/h_sweep_cli.csv
$(figure4_OUTPUTS) &: experiments/figure4/plot.gp $(figure4_SCENES) $(IMPACT) $(figure4_DRIVER)
	@mkdir -p $(RESULTS)/figure4 figures
	for scene in no_cor cor075; do for method in direct fb_newton exact; do \
	  channels='["u","v","N_scheme","E"]'; [ $$method = exact ] && channels='["u","v","N","E"]'; \
	  $(IMPACT) run experiments/figure4/$$scene.toml --set method.name=$$method --quiet \
	    --set "output.channels=$$channels" \
	    --out $(RESULTS)/figure4/$${scene}_$$method.csv || exit 1; done; done
	$(IMPACT) run experiments/figure4/no_cor.toml --set method.free_flight=paper --quiet \
	  --out $(RESULTS)/figure4/no_cor_direct_paper.csv
	$(figure4_DRIVER) $(RESULTS)/figure4
	$(IMPACT) sweep experiments/figure4/no_cor.toml --vary time.h=1e-4:1e-2:41:log \
	  --summary rest_time,E_T,impacts --quiet --out $(RESULTS)/figure4/h_sweep_cli.csv
	gnuplot -e "results='$(RESULTS)/figure4'" experiments/figure4/plot.gp
	$(call FIX_PDF_DATE,figures/figure4.pdf)
