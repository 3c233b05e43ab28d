# The ball on a vibrating table: bifurcation diagrams of exact, direct and moreau_jean, the
# period-1 thresholds each method shows against the closed forms (paper_notes/vibrating_table.md),
# one trajectory per regime. The PDFs are the vector copies (10^5-point diagrams make SVGs of MBs).
EXPERIMENTS += vibrating_table
vibrating_table_DRIVER := $(BUILD)/experiments/vibrating_table/exp_vibrating_table
vibrating_table_FIGURES := vibrating_table vibrating_table_steppers vibrating_table_thresholds \
    vibrating_table_trajectories
vibrating_table_OUTPUTS := $(foreach f,$(vibrating_table_FIGURES),figures/$(f).png figures/$(f).pdf) \
    $(RESULTS)/vibrating_table/summary.toml
$(vibrating_table_OUTPUTS) &: experiments/vibrating_table/plot.gp $(vibrating_table_DRIVER)
	@mkdir -p $(RESULTS)/vibrating_table figures
	$(vibrating_table_DRIVER) $(RESULTS)/vibrating_table
	gnuplot -e "results='$(RESULTS)/vibrating_table'" experiments/vibrating_table/plot.gp
	for f in $(vibrating_table_FIGURES); do $(call FIX_PDF_DATE,figures/$$f.pdf); done
