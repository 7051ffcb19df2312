# csgray: the two commands of the README, and their parts.
#   make run   install what is missing, build, render and export the showcase
#   make test  install what is missing, build, run every test
#   make bench run the benchmarks (see docs/performance.md)

BUILD      ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
CSGRAY     := $(BUILD)/cli/csgray

# Debian 12 packages the build and the tests need.
PACKAGES := build-essential cmake pkg-config \
            libcgal-dev libopenmesh-dev libglm-dev libopenimageio-dev \
            liblua5.4-dev libcli11-dev libgtest-dev libtbb-dev lib3mf-dev libzip-dev zlib1g-dev time

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build run test bench clean

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
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

run: build
	@mkdir -p out
	$(CSGRAY) render examples/showcase.lua -o out/showcase.png --size 1024x768
	$(CSGRAY) export examples/showcase.lua -o out/showcase.stl
	@echo "The rendered showcase is out/showcase.png, its printable mesh out/showcase.stl"

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	bench/run.sh $(CSGRAY)

clean:
	rm -rf $(BUILD) out
