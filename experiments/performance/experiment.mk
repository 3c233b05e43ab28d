# Throughput: `make performance` runs the Google Benchmark micro-benchmarks and plots
# $(TIMING_DIR)/performance.png (`make refresh-timing-figures` copies it to figures/). Not part
# of `make all`: it measures this machine (about 3 minutes of repetitions) rather than reproducing
# the paper. Google Benchmark (libbenchmark-dev) is added to the packages `make deps` installs,
# for this target only.
PERFORMANCE_DRIVER := $(BUILD)/experiments/performance/exp_performance
TIMING_FIGURES += performance.png performance.svg
.PHONY: performance
performance: export IMPACT_EXTRA_PACKAGES += libbenchmark-dev
performance: build
	@test -x $(PERFORMANCE_DRIVER) || { echo "performance: Google Benchmark was not found when $(BUILD) was configured (Debian: libbenchmark-dev)"; exit 1; }
	@mkdir -p $(RESULTS)/performance $(TIMING_DIR)
	$(PERFORMANCE_DRIVER) $(RESULTS)/performance $(IMPACT) --benchmark_color=false
	gnuplot -e "results='$(RESULTS)/performance'; out='$(TIMING_DIR)'" experiments/performance/plot.gp
