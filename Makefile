# Quick start: `make run` (install what is missing, build, run the flagship demo), `make test`.
BUILD      := build/release
NCKIT      := $(BUILD)/src/nckit
DEMO       := examples/01_mill_pocket.ngc
JOBS       ?= 2

.PHONY: all deps configure build run test test-unit test-asan bench fuzz clean hal hal-install

all: build

deps:
	@bash scripts/deps.sh

configure: deps
	@cmake --preset release >/dev/null

build: configure
	@cmake --build --preset release -j $(JOBS)

run: build
	@echo "== nckit moves $(DEMO) --summary"
	@$(NCKIT) moves $(DEMO) --summary
	@echo "== first moves"
	@$(NCKIT) moves $(DEMO) | head -n 12
	@echo "== nckit plan $(DEMO)   (S-curve look-ahead: cycle time and each axis's peaks)"
	@$(NCKIT) plan $(DEMO)
	@echo "== the eccentric shaft, a Custom Macro B program"
	@$(NCKIT) moves examples/eccentric/eccentric_shaft.nc --machine examples/machines/lathe.toml \
	    --library examples/eccentric/library --summary
	@echo "== the same shaft by electronic cam: X slaved to the spindle angle"
	@$(NCKIT) eccentric examples/eccentric/eccentric_cam.toml --machine examples/machines/lathe.toml
	@echo "== crosshatch laser hardening of a bore, 12 heads at 30 degrees"
	@$(NCKIT) crosshatch examples/crosshatch/bore_12heads_30deg.toml
	@echo "== oval piston on a fast tool servo at 2500 rpm: no compensation, feedforward, learning"
	@$(NCKIT) piston examples/piston/piston.toml

test: build
	@ctest --preset release

test-unit: build
	@ctest --preset release -L unit

# The unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer.
test-asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan -j $(JOBS)
	@ctest --preset asan

bench: build
	@bash bench/run_all.sh

# The LinuxCNC HAL components (docs/hal-cam.md); hal-install puts them where loadrt looks.
hal: configure
	@cmake --build --preset release -j $(JOBS) --target hal

hal-install: configure
	@cmake --build --preset release -j $(JOBS) --target hal-install

# Differential fuzzing against LinuxCNC's rs274: 500 seeded random programs (CTest runs 20).
fuzz: build
	@flock /tmp/linuxcnc.lock python3 tests/programs/fuzz_linuxcnc.py --count 500 --seed 11

clean:
	@rm -rf build
