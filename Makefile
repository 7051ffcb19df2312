# csgray: the two commands of the README, and their parts.
#   make run   install what is missing, build, render and export the showcase
#   make test  install what is missing, build, run every test
#   make bench run the benchmarks (see docs/performance.md)
#   make fuzz  build the readers' libFuzzer targets (meshes, SVG, PNG) with clang and run
#              each for FUZZ_SECONDS (default 60)

BUILD      ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
# Instruction set (README, "Building by hand"): auto, x86-64-v3 or portable;
# read when $(BUILD) is first configured.
ARCH       ?= auto
CSGRAY     := $(BUILD)/cli/csgray

# Debian 12 packages the build and the tests need (chromium: the browser test
# of csgray view, tests/browser/).
PACKAGES := build-essential cmake pkg-config \
            libcgal-dev libopenmesh-dev libglm-dev libopenimageio-dev \
            liblua5.4-dev libcli11-dev libgtest-dev libtbb-dev lib3mf-dev libzip-dev zlib1g-dev time \
            libcpp-httplib-dev chromium \
            libfreetype-dev libharfbuzz-dev libfontconfig-dev fonts-dejavu-core fonts-liberation

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build run test bench fuzz clean

all: build

# Installs only what is missing, so a second run costs one dpkg query.
deps:
	@missing=$$(dpkg-query -W -f='$${Package} $${Status}\n' $(PACKAGES) 2>/dev/null \
	    | awk '$$NF == "installed" {print $$1}' | sort > .deps-installed; \
	  for p in $(PACKAGES); do grep -qx "$$p" .deps-installed || echo $$p; done); \
	rm -f .deps-installed; \
	if [ -n "$$missing" ]; then \
	  echo "Installing missing packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DCSGRAY_ARCH=$(ARCH)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	@mkdir -p out
	$(CSGRAY) render examples/showcase.lua -o out/showcase.png --size 1024x768
	$(CSGRAY) export examples/showcase.lua -o out/showcase.stl
	$(CSGRAY) check examples/showcase.lua
	@echo "The rendered showcase is out/showcase.png, its printable mesh out/showcase.stl"

# The browser test (tests/browser/run.sh) needs node and npm too, from
# Debian when missing, and installs puppeteer-core into tests/browser/ on its
# first run; without chromium or node it is skipped, and says why.
test: build
	@command -v npm >/dev/null || \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends nodejs npm || \
	  echo "no npm: the browser test will be skipped"
	@[ -x /usr/bin/chromium ] || echo "no chromium: the browser test will be skipped (make deps installs it)"
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Manifold's WebAssembly build, the anchor of the export table, from the npm
# registry into bench/manifold/node_modules (bench only: never run or test).
MANIFOLD := bench/manifold/node_modules/manifold-3d/package.json
$(MANIFOLD): bench/manifold/package.json
	@command -v npm >/dev/null || \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends nodejs npm
	cd bench/manifold && npm install --no-audit --no-fund --loglevel=error
	@touch $@

# POV-Ray 3.7, the anchor of the render rows, and OpenImageIO's idiff, which
# compares their images: installed by the benchmark only, never by run or
# test.
POVRAY := /usr/bin/povray /usr/bin/idiff
$(POVRAY):
	DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends povray \
	  openimageio-tools

# OpenSCAD and a virtual display for its preview (the comparison with
# csgray view): likewise the benchmark's only.
OPENSCAD := /usr/bin/openscad /usr/bin/xvfb-run
$(OPENSCAD):
	DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends openscad xvfb

bench: build $(MANIFOLD) $(POVRAY) $(OPENSCAD)
	bench/run.sh $(CSGRAY)

# The fuzzers need clang and its sanitizer runtime (Debian: clang,
# libclang-rt-dev); new inputs they find go to a scratch copy of the corpus.
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 60
# lib3mf, through libzip, leaks a little on every file it refuses: not
# csgray's to find, so the 3MF target does not look for leaks.
fuzz: deps
	@command -v clang++ >/dev/null && dpkg -s libclang-rt-dev >/dev/null 2>&1 || \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends clang libclang-rt-dev
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DCSGRAY_FUZZ=ON -DCSGRAY_TESTS=OFF \
	  -DCMAKE_CXX_COMPILER=clang++
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_stl fuzz_obj fuzz_off fuzz_ply fuzz_3mf fuzz_svg fuzz_png
	for format in stl obj off ply 3mf svg png; do \
	  leaks=1; [ $$format = 3mf ] && leaks=0; \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$format && \
	  $(FUZZ_BUILD)/fuzz/fuzz_$$format -max_total_time=$(FUZZ_SECONDS) -detect_leaks=$$leaks \
	    $(FUZZ_BUILD)/corpus/$$format fuzz/corpus/$$format || exit 1; \
	done

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD) out
