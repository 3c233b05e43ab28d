# The impact oscillator u'' = -u - cos(omega t) + N, u >= phi, COR r (beyond the paper): the
# period-one orbit in closed form against runs, its thresholds, bifurcation diagrams, grazing,
# chatter; and work against precision of the methods that take a force of the state, whose CPU
# times make it a timing figure (written to $(TIMING_DIR); see the Makefile).
EXPERIMENTS += impact_oscillator
impact_oscillator_DRIVER := $(BUILD)/experiments/impact_oscillator/exp_impact_oscillator
impact_oscillator_FIGURES := impact_oscillator impact_oscillator_orbit impact_oscillator_grazing \
    impact_oscillator_chatter
impact_oscillator_TIMING := impact_oscillator_work_precision.png impact_oscillator_work_precision.svg
TIMING_FIGURES += $(impact_oscillator_TIMING)
impact_oscillator_OUTPUTS := $(foreach f,$(impact_oscillator_FIGURES),figures/$(f).png figures/$(f).pdf) \
    $(addprefix $(TIMING_DIR)/,$(impact_oscillator_TIMING)) $(RESULTS)/impact_oscillator/summary.toml
$(impact_oscillator_OUTPUTS) &: experiments/impact_oscillator/plot.gp \
    experiments/impact_oscillator/periodic.toml experiments/impact_oscillator/chaotic.toml \
    $(impact_oscillator_DRIVER)
	@mkdir -p $(RESULTS)/impact_oscillator figures $(TIMING_DIR)
	$(impact_oscillator_DRIVER) $(RESULTS)/impact_oscillator
	gnuplot -e "results='$(RESULTS)/impact_oscillator'; timing='$(TIMING_DIR)'" \
	  experiments/impact_oscillator/plot.gp
	for f in $(impact_oscillator_FIGURES); do $(call FIX_PDF_DATE,figures/$$f.pdf); done
