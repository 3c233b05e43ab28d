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

# `make all` prints one line per step; the sub-makes say nothing about directories.
MAKEFLAGS += --no-print-directory

# Figures are byte-reproducible, so that `make all` leaves the committed ones unchanged. pdfcairo
# writes the time of the run into a PDF's /CreationDate, and the cairo of Debian 12 (1.16) ignores
# SOURCE_DATE_EPOCH, so $(call FIX_PDF_DATE,file.pdf) overwrites that date with SOURCE_DATE_EPOCH's,
# padded to the same length so that the PDF's cross-reference offsets stay valid.
export SOURCE_DATE_EPOCH := 0
PDF_DATE := $(shell date -u -d @$(SOURCE_DATE_EPOCH) +%Y%m%d%H%M%S)
FIX_PDF_DATE = perl -0777 -pi -e 's{/CreationDate \(D:[^)]*\)}{my $$d = "/CreationDate (D:$(PDF_DATE)Z)"; $$d . " " x (length($$&) - length($$d))}ge' $(1)

# Shell code: the seconds since $$start (start=$$(date +%s%N)), to one decimal.
SECONDS_SINCE = ms=$$(( ($$(date +%s%N) - start) / 1000000 )); printf '%d.%d' $$((ms / 1000)) $$((ms % 1000 / 100))

# Figures that show this machine's CPU or wall time differ from run to run. Their experiments
# write them to $(TIMING_DIR), so that `make all` leaves the committed copies in figures/ alone;
# `make refresh-timing-figures` measures again and copies them over. Each experiment.mk adds the
# names of its timing figures to TIMING_FIGURES.
TIMING_DIR := $(RESULTS)/figures
TIMING_FIGURES :=

# The rule of an experiment whose driver writes results/<name>/ and whose plot.gp draws its
# figures: $(eval $(call driver_and_plot,NAME,FIGURES,EXTRA_PREREQUISITES)) in its experiment.mk.
define driver_and_plot
EXPERIMENTS += $(1)
$(1)_DRIVER := $$(BUILD)/experiments/$(1)/exp_$(1)
$(1)_OUTPUTS := $$(addprefix figures/,$(2)) $$(RESULTS)/$(1)/summary.toml
$$($(1)_OUTPUTS) &: experiments/$(1)/plot.gp $$($(1)_DRIVER) $(3)
	@mkdir -p $$(RESULTS)/$(1) figures
	$$($(1)_DRIVER) $$(RESULTS)/$(1)
	gnuplot -e "results='$$(RESULTS)/$(1)'" experiments/$(1)/plot.gp
endef

EXPERIMENTS :=
include $(wildcard experiments/*/experiment.mk)

.PHONY: all deps configure build tools test clean experiments claims claims-md help refresh-timing-figures \
  $(EXPERIMENTS) \
  $(EXPERIMENTS:%=run-%) $(EXPERIMENTS:%=outputs-%)
.DEFAULT_GOAL := help

help:
	@echo "make all          install what is missing, build, run every experiment, plot every figure"
	@echo "make test         install what is missing, build, run the test suite (ctest)"
	@echo "make <experiment> run one experiment and plot its figure; experiments: $(EXPERIMENTS)"
	@echo "make claims       print the claims ledger's verdicts with the latest measured numbers"
	@echo "make claims-md    regenerate paper_notes/claims.md from claims_source.md and the references"
	@echo "make build        configure and build everything, tests included"
	@echo "make python       build the Python module impact and print the PYTHONPATH that imports it"
	@echo "make performance  Google Benchmark throughput (ns per step) and the ensemble; not in all"
	@echo "make work_precision-siconos  the work-precision study with Siconos's solvers (installs it)"
	@echo "make refresh-timing-figures  measure again and update the committed timing figures:"
	@echo "                  $(sort $(basename $(TIMING_FIGURES)))"
	@echo "make clean        remove $(BUILD)/ and $(RESULTS)/"
	@echo "make asan-test    the test suite under AddressSanitizer + UBSan, in $(ASAN_BUILD)/"
	@echo "make fuzz         fuzz the scene reader and --set for $(FUZZ_SECONDS) s (clang); fuzz-long: 30 min"
	@echo "make determinism  check that an -O0 build writes the same bytes as $(BUILD)/"
	@echo "make odr-check    link the library with -flto into one shared object: fails on an ODR violation"
	@echo "make examples     install to a temporary prefix, build examples/ against it and run them"
	@echo "make docs         the API reference of the installed headers (Doxygen; installs it): $(BUILD)/docs/html"

all:
	@start=$$(date +%s%N); $(MAKE) tools && $(MAKE) experiments && \
	  echo "all: build and $(words $(EXPERIMENTS)) experiments in $$($(SECONDS_SINCE)) s"

deps:
	@bash .ci/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) > $(BUILD).configure.log 2>&1 || { cat $(BUILD).configure.log; exit 1; }

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# What the experiments run (the CLI, the claims tool, the drivers), without the test suite.
# Its compiler output goes to $(BUILD).build.log, shown when the build fails.
tools: configure
	@start=$$(date +%s%N); \
	cmake --build $(BUILD) -j $(JOBS) --target impact_experiments > $(BUILD).build.log 2>&1 || \
	  { cat $(BUILD).build.log; echo "build: failed (log: $(BUILD).build.log)"; exit 1; }; \
	echo "build: done in $$($(SECONDS_SINCE)) s"

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The Python module alone (docs/python.md), and how to import it.
.PHONY: python
python: configure
	@cmake --build $(BUILD) -j $(JOBS) --target impact_python
	@echo "export PYTHONPATH=$(abspath $(BUILD))/python  # then: /usr/bin/python3 -c 'import impact'"

# Each experiment's experiment.mk adds its name to EXPERIMENTS and lists its outputs in
# <name>_OUTPUTS with real file dependencies, so a second `make all` redoes nothing.
experiments: $(EXPERIMENTS:%=run-%)

$(EXPERIMENTS): tools
	@$(MAKE) run-$@

# One line per experiment. What its commands print goes to results/<name>/make.log, which is shown
# when one of them fails.
$(EXPERIMENTS:%=run-%): run-%:
	@start=$$(date +%s%N); \
	if $(MAKE) -q outputs-$* 2>/dev/null; then echo "$*: up to date"; else \
	  mkdir -p $(RESULTS)/$*; \
	  if $(MAKE) outputs-$* > $(RESULTS)/$*/make.log 2>&1; then \
	    echo "$*: done in $$($(SECONDS_SINCE)) s"; \
	  else cat $(RESULTS)/$*/make.log; echo "$*: failed (log: $(RESULTS)/$*/make.log)"; exit 1; fi; \
	fi

.SECONDEXPANSION:
$(EXPERIMENTS:%=outputs-%): outputs-%: $$($$*_OUTPUTS)

# The timing figures' experiments run again (performance included: ~3 minutes of benchmarks),
# whether or not their inputs changed, then their figures are copied from $(TIMING_DIR) to
# figures/, to be committed.
refresh-timing-figures:
	@rm -f $(addprefix $(TIMING_DIR)/,$(TIMING_FIGURES))
	@$(MAKE) work_precision stability performance impact_oscillator
	@cp $(addprefix $(TIMING_DIR)/,$(TIMING_FIGURES)) figures/
	@echo "refresh-timing-figures: $(words $(TIMING_FIGURES)) files copied to figures/"

# Siconos's Moreau-Jean and LSODAR beside every method in the work-precision study: opt-in, since it
# installs libsiconos-kernel-dev and builds the study again in build-siconos/ (the figures go to
# $(TIMING_DIR), as the study's always do; refresh-timing-figures copies them to figures/).
SICONOS_BUILD ?= build-siconos
.PHONY: work_precision-siconos
work_precision-siconos:
	@IMPACT_EXTRA_PACKAGES=libsiconos-kernel-dev bash .ci/deps.sh
	@rm -f $(addprefix $(TIMING_DIR)/,$(work_precision_FIGURES))
	@$(MAKE) BUILD=$(SICONOS_BUILD) CMAKE_FLAGS="$(CMAKE_FLAGS) -DIMPACT_SICONOS=ON" work_precision

# The claims ledger: `claims` prints the verdicts with the numbers of the latest results (else the
# committed references); `claims-md` regenerates paper_notes/claims.md from claims_source.md and
# experiments/*/reference.toml. The tool's build goes to a log, so only the table is printed.
CLAIMS_TOOL = @MAKEFLAGS= MAKELEVEL= cmake --build $(BUILD) --target impact_claims \
	  > $(BUILD).claims.log 2>&1 || { cat $(BUILD).claims.log; exit 1; }
claims: configure
	$(CLAIMS_TOOL)
	@$(BUILD)/impact-claims table paper_notes/claims_source.md $(RESULTS) experiments

claims-md: configure
	$(CLAIMS_TOOL)
	@$(BUILD)/impact-claims markdown paper_notes/claims_source.md experiments paper_notes/claims.md
	@echo "wrote paper_notes/claims.md"

clean:
	rm -rf $(BUILD) $(BUILD).configure.log $(RESULTS)

# The examples against the installed library (find_package(impact 0.2 COMPONENTS scene) and
# pkg-config), as a program outside the repository builds them: only the libraries and the
# command are built here.
.PHONY: examples
examples: configure
	@cmake --build $(BUILD) -j $(JOBS) --target impact_core impact_scene impact_cli
	@JOBS=$(JOBS) bash examples/check_installed.sh $(BUILD)

# The API reference (docs/library.md): Doxygen over the installed headers, failing on any warning.
# doxygen is installed for this target only, before the configure that finds it.
.PHONY: docs
docs:
	@IMPACT_EXTRA_PACKAGES=doxygen bash .ci/deps.sh
	@$(MAKE) configure
	@cmake --build $(BUILD) --target impact_docs

# Hardening (tests/README.md): the test suite under AddressSanitizer and UBSan, the libFuzzer
# target of the scene reader and --set (tests/fuzz; clang is installed for it only), and
# byte-identical output from an -O0 build (a second build, so a script rather than a ctest).
ODR_BUILD ?= build-odr
.PHONY: odr-check
# Every object of src/ without a main(), compiled with -flto and linked into one shared object with
# -Werror=odr -Werror=lto-type-mismatch: a type or function defined twice, differently, fails here.
odr-check: deps
	@cmake -S . -B $(ODR_BUILD) $(CMAKE_FLAGS) -DIMPACT_ODR_CHECK=ON -DIMPACT_BUILD_TESTS=OFF \
	  > $(ODR_BUILD).configure.log 2>&1 || { cat $(ODR_BUILD).configure.log; exit 1; }
	@cmake --build $(ODR_BUILD) --target impact_odr_check -j $(JOBS)
	@echo "odr-check: the library links as one LTO shared object without ODR violations"

ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
O0_BUILD ?= build-O0
FUZZ_SECONDS ?= 60
.PHONY: asan-test fuzz fuzz-long determinism

asan-test: deps
	@cmake -S . -B $(ASAN_BUILD) $(CMAKE_FLAGS) -DIMPACT_SANITIZE=ON -DIMPACT_PYTHON=OFF \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  > $(ASAN_BUILD).configure.log 2>&1 || { cat $(ASAN_BUILD).configure.log; exit 1; }
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	cd $(ASAN_BUILD) && ctest --output-on-failure -j $(JOBS) -LE scale

fuzz:
	@IMPACT_EXTRA_PACKAGES="clang libclang-rt-14-dev" bash .ci/deps.sh
	@CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DIMPACT_FUZZ=ON -DIMPACT_BUILD_TESTS=OFF \
	  -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" \
	  > $(FUZZ_BUILD).configure.log 2>&1 || { cat $(FUZZ_BUILD).configure.log; exit 1; }
	@cmake --build $(FUZZ_BUILD) --target fuzz_scene -j $(JOBS)
	@bash tests/fuzz/seeds.sh $(FUZZ_BUILD)/seeds
	@mkdir -p $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/findings
	$(FUZZ_BUILD)/tests/fuzz/fuzz_scene -max_total_time=$(FUZZ_SECONDS) -dict=tests/fuzz/scene.dict \
	  -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/findings/ \
	  $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/seeds

fuzz-long:
	@$(MAKE) fuzz FUZZ_SECONDS=1800

determinism: build
	@cmake -S . -B $(O0_BUILD) $(CMAKE_FLAGS) -DCMAKE_BUILD_TYPE=Debug -DIMPACT_BUILD_TESTS=OFF \
	  > $(O0_BUILD).configure.log 2>&1 || { cat $(O0_BUILD).configure.log; exit 1; }
	@cmake --build $(O0_BUILD) --target impact_cli -j $(JOBS)
	bash tests/determinism.sh $(BUILD) $(O0_BUILD)
