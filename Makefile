# mirage: the front door.  `make render` and `make test` take a fresh Debian 12 machine
# from nothing to working: they install the Debian packages the project needs, configure,
# build and then render or test.
#
#   make                 install what is missing, build build/mirage
#   make render          compile scenes/desert.pov to a banded medium and its corrected camera,
#                        and render it with POV-Ray into build/render/NAME/NAME.png
#                        (SCENE=scenes/road.pov W=640 H=480 TOL=0.5 to choose)
#   make trace           render the scene with the built-in tracer along the curved rays
#                        (build/render/NAME-trace.png; same SCENE, W, H, TOL)
#                        Colour (docs/colour.md): a scene that declares Mirage_Wavelengths is
#                        rendered in colour by both; WAVELENGTHS=610,550,465 asks for it (real
#                        air only): make render then compiles one design per wavelength into
#                        build/render/NAME/NAME-<nm>nm/ and combines POV-Ray's channels
#   make test            build and run every test through CTest
#   make bench           Google Benchmark for the path kernels
#   make study           band designs compared on a scene's continuum of camera rays (build/study/NAME/:
#                        study.csv, summary.md, error_vs_elevation.png, error_vs_crossings.png;
#                        SCENE, W, H)
#   make compare         band models against the continuous tracer: error against run time
#                        (build/compare/NAME/: results.csv, error_vs_time.png, contact_sheet.png,
#                        summary.md; SCENE, and W H or CW CH, default 320x240: a few minutes)
#   make animate         every frame of an animated scene (default scenes/walk.pov, FRAMES=24,
#                        320x240 unless W H are given, MODEL=bands or trace) into
#                        build/animate/NAME/: NAME.mp4, NAME.gif, vanishing.png, summary.md
#   make fuzz            libFuzzer on the scene parser and the Mirage_ settings reader for
#                        FUZZ_SECONDS (default 600) in FUZZ_JOBS processes (default 1), in
#                        build-fuzz/ with clang; installs FUZZ_PACKAGES first (make test
#                        needs none of them).  FUZZ_TARGET=csv, sounding or truetype for the
#                        other readers; FUZZ_SANITIZERS=0 for the faster plain build
#   make clean

BUILD   ?= build
SCENE   ?= scenes/desert.pov
W       ?= 640
H       ?= 480
TOL     ?=
WAVELENGTHS ?=
# make compare renders every setting: its own size, smaller, unless W and H are given.
CW      ?= $(if $(filter command line,$(origin W)),$(W),320)
CH      ?= $(if $(filter command line,$(origin H)),$(H),240)
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
FUZZ_SECONDS ?= 600
FUZZ_JOBS    ?= 1
FUZZ_BUILD   ?= build-fuzz
NAME    := $(basename $(notdir $(SCENE)))
# make animate: its own default scene and size.
ASCENE  := $(if $(filter command line,$(origin SCENE)),$(SCENE),scenes/walk.pov)
ANAME   := $(basename $(notdir $(ASCENE)))
FRAMES  ?= 24
MODEL   ?= bands
AW      ?= $(if $(filter command line,$(origin W)),$(W),320)
AH      ?= $(if $(filter command line,$(origin H)),$(H),240)

# Debian 12 packages the build, the tests and the renders need.
PACKAGES := g++ make cmake pkg-config povray povray-includes povray-examples libopenimageio-dev libpng-dev \
            openimageio-tools libglm-dev libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev \
            gnuplot-nox fonts-dejavu-core ffmpeg parallel munge slurmctld slurmd slurm-client \
            python3
# What make fuzz needs besides: clang and its libFuzzer and sanitizer runtimes.
FUZZ_PACKAGES := clang-14 libclang-rt-14-dev

.PHONY: all deps configure build test render trace bench compare animate study fuzz clean

all: build

deps:
	@sh tools/install-deps.sh $(PACKAGES)

$(BUILD)/CMakeCache.txt: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

render: build
	$(BUILD)/mirage compile $(SCENE) --width $(W) --height $(H) $(if $(TOL),--tolerance $(TOL)) \
	    $(if $(WAVELENGTHS),--wavelengths $(WAVELENGTHS)) -o $(BUILD)/render/$(NAME) --render

trace: build
	@mkdir -p $(BUILD)/render
	$(BUILD)/mirage trace $(SCENE) --width $(W) --height $(H) $(if $(TOL),--tolerance $(TOL)) \
	    $(if $(WAVELENGTHS),--wavelengths $(WAVELENGTHS)) -o $(BUILD)/render/$(NAME)-trace.png

compare: build
	$(BUILD)/mirage compare $(SCENE) -W $(CW) -H $(CH) -o $(BUILD)/compare/$(NAME)

animate: build
	$(BUILD)/mirage animate $(ASCENE) --frames $(FRAMES) -W $(AW) -H $(AH) --model $(MODEL) \
	    $(if $(TOL),--tolerance $(TOL)) -o $(BUILD)/animate/$(ANAME)

study: build
	$(BUILD)/mirage study $(SCENE) -W $(W) -H $(H) -o $(BUILD)/study/$(NAME)

bench: build
	$(BUILD)/mirage_bench

# The corpus grows in $(FUZZ_BUILD)/corpus-$(FUZZ_TARGET) from run to run; a crashing input is
# written to $(FUZZ_BUILD)/artifacts/ (and belongs in tests/fuzz/crashes/ once fixed).  The stack
# is 1 GiB: with AddressSanitizer a level of the parser's nesting takes up to about 140 KiB, and
# in the default 8 MiB the parse would stop at its stack (with its message) some 50 levels deep,
# short of the 256 levels it allows.  FUZZ_SANITIZERS=0 builds in $(FUZZ_BUILD)-plain without
# the sanitizers (libFuzzer's coverage alone): several times the executions a second.
FUZZ_TARGET     ?= scene
FUZZ_SANITIZERS ?= 1
FUZZ_DIR        := $(FUZZ_BUILD)$(if $(filter 0,$(FUZZ_SANITIZERS)),-plain)
FUZZ_SEEDS_scene    := $(FUZZ_DIR)/seeds -dict=$(FUZZ_DIR)/scene.dict
FUZZ_SEEDS_csv      := tests/data tests/fuzz/crashes/csv
FUZZ_SEEDS_sounding := $(FUZZ_DIR)/seeds-sounding tests/fuzz/crashes/sounding
FUZZ_SEEDS_truetype := $(FUZZ_DIR)/seeds-truetype tests/fuzz/crashes/truetype
FUZZ_SEED_FILES_sounding := scenes/hot_road.csv docs/sounding_example.csv
FUZZ_SEED_FILES_truetype := $(wildcard /usr/share/povray-3.7/include/*.ttf)
FUZZ_MAX_LEN_truetype := 65536
fuzz: deps
	@sh tools/install-deps.sh $(FUZZ_PACKAGES)
	@test -f $(FUZZ_DIR)/CMakeCache.txt || cmake -S . -B $(FUZZ_DIR) \
	    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DMIRAGE_FUZZ=ON \
	    -DMIRAGE_FUZZ_SANITIZERS=$(if $(filter 0,$(FUZZ_SANITIZERS)),OFF,ON)
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target mirage_$(FUZZ_TARGET)_fuzzer
	@mkdir -p $(FUZZ_DIR)/corpus-$(FUZZ_TARGET) $(FUZZ_DIR)/artifacts
	python3 tools/fuzz_corpus.py $(FUZZ_DIR)/seeds $(FUZZ_DIR)/scene.dict
	@mkdir -p $(FUZZ_DIR)/seeds-$(FUZZ_TARGET)
	$(if $(FUZZ_SEED_FILES_$(FUZZ_TARGET)),cp $(FUZZ_SEED_FILES_$(FUZZ_TARGET)) $(FUZZ_DIR)/seeds-$(FUZZ_TARGET)/)
	ulimit -s 1048576 && $(FUZZ_DIR)/mirage_$(FUZZ_TARGET)_fuzzer $(FUZZ_DIR)/corpus-$(FUZZ_TARGET) \
	    $(FUZZ_SEEDS_$(FUZZ_TARGET)) -max_total_time=$(FUZZ_SECONDS) \
	    -max_len=$(or $(FUZZ_MAX_LEN_$(FUZZ_TARGET)),4096) \
	    -timeout=60 -rss_limit_mb=2048 -print_final_stats=1 \
	    $(if $(filter-out 1,$(FUZZ_JOBS)),-fork=$(FUZZ_JOBS)) \
	    -artifact_prefix=$(FUZZ_DIR)/artifacts/

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) $(FUZZ_BUILD)-plain
