# Throughput: `make performance` runs the Google Benchmark micro-benchmarks and plots
# figures/performance.png. Not part of `make all`: it measures this machine (about 3 minutes of
# repetitions) rather than reproducing the paper. Google Benchmark (libbenchmark-dev) is added to
# the packages `make deps` installs, for this target only.
PERFORMANCE_DRIVER := $(BUILD)/experiments/performance/exp_performance
.PHONY: performance
performance: export IMPACT_EXTRA_PACKAGES += libbenchmark-dev
performance: build
	@test -x $(PERFORMANCE_DRIVER) || { echo "performance: Google Benchmark was not found when $(BUILD) was configured (Debian: libbenchmark-dev)"; exit 1; }
	@mkdir -p $(RESULTS)/performance figures
	$(PERFORMANCE_DRIVER) $(RESULTS)/performance $(IMPACT) --benchmark_color=false
	gnuplot -e "results='$(RESULTS)/performance'" experiments/performance/plot.gp
