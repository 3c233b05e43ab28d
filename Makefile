# impact: `make all` reproduces everything, `make test` runs the test suite.
# Both install missing Debian packages first (see .ci/deps.sh).
BUILD ?= build
JOBS ?= 2
CMAKE_FLAGS ?=
ifeq ($(CI),true)
CMAKE_FLAGS += -DIMPACT_WERROR=ON
endif
IMPACT := $(BUILD)/impact
RESULTS := results

EXPERIMENTS :=
include $(wildcard experiments/*/experiment.mk)

.PHONY: all deps configure build test clean experiments claims help $(EXPERIMENTS) $(EXPERIMENTS:%=run-%)
.DEFAULT_GOAL := help

help:
	@echo "make all          install what is missing, build, run every experiment, plot every figure"
	@echo "make test         install what is missing, build, run the test suite (ctest)"
	@echo "make <experiment> run one experiment and plot its figure; experiments: $(EXPERIMENTS)"
	@echo "make claims       print the claims ledger's verdicts with the latest measured numbers"
	@echo "make build        configure and build only ($(BUILD)/impact and the drivers)"
	@echo "make clean        remove $(BUILD)/ and $(RESULTS)/"

all: build
	@$(MAKE) --no-print-directory experiments

deps:
	@bash .ci/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) > $(BUILD).configure.log 2>&1 || { cat $(BUILD).configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Each experiment's experiment.mk adds its name to EXPERIMENTS and lists its outputs in
# <name>_OUTPUTS with real file dependencies, so a second `make all` redoes nothing.
experiments: $(EXPERIMENTS:%=run-%)

$(EXPERIMENTS): build
	@$(MAKE) --no-print-directory run-$@

.SECONDEXPANSION:
$(EXPERIMENTS:%=run-%): run-%: $$($$*_OUTPUTS)

# The claims ledger's verdict table with the numbers of the latest results.
claims: build
	@$(BUILD)/impact-claims paper_notes/claims.md $(RESULTS)

clean:
	rm -rf $(BUILD) $(BUILD).configure.log $(RESULTS)
