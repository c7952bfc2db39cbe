# Quick start: `make run` (install what is missing, build, run the flagship demo), `make test`.
BUILD      := build/release
NCKIT      := $(BUILD)/src/nckit
DEMO       := examples/01_mill_pocket.ngc
JOBS       ?= 2
PREFIX     ?= /usr/local
# Seconds each fuzz target runs under `make fuzz` (CI: 60).
FUZZ_SECONDS ?= 30

.PHONY: all deps deps-test configure build build-nckit run install test test-unit test-asan bench fuzz clean \
        hal hal-install install-linuxcnc-plugin fuzz-linuxcnc

all: build

# Package groups (scripts/deps.sh): `make run` needs the build group only; LinuxCNC, the test
# tools and Google Benchmark come with `make test` and `make bench`.
deps:
	@bash scripts/deps.sh build

deps-test:
	@bash scripts/deps.sh build test linuxcnc

configure: deps
	@cmake --preset release >/dev/null

build: configure
	@cmake --build --preset release -j $(JOBS)

# The command line alone: what the demo and `make install` need.
build-nckit: configure
	@cmake --build --preset release -j $(JOBS) --target nckit

install: build-nckit
	@cmake --install $(BUILD) --prefix $(PREFIX) --component nckit >/dev/null
	@echo "nckit installed as $(PREFIX)/bin/nckit"

run: build-nckit
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

test: deps-test
	@cmake --preset release >/dev/null
	@cmake --build --preset release -j $(JOBS)
	@ctest --preset release

test-unit: build
	@ctest --preset release -L unit

# The unit tests again under AddressSanitizer and UndefinedBehaviorSanitizer.
test-asan: deps-test
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan -j $(JOBS)
	@ctest --preset asan

# The LinuxCNC interpreter plug-in (built when linuxcnc-uspace-dev is installed) into LinuxCNC's
# library folder, where an INI's `[TASK] INTERPRETER = libnckit_linuxcnc.so` finds it (as root).
install-linuxcnc-plugin: build
	@install -m 644 $(BUILD)/src/linuxcnc_interp/libnckit_linuxcnc.so /usr/lib/linuxcnc/
	@echo "installed /usr/lib/linuxcnc/libnckit_linuxcnc.so"

# The LinuxCNC HAL components (docs/hal-cam.md); hal-install puts them where loadrt looks.
hal: configure
	@cmake --build --preset release -j $(JOBS) --target hal

hal-install: configure
	@cmake --build --preset release -j $(JOBS) --target hal-install

bench:
	@bash scripts/deps.sh build bench linuxcnc
	@cmake --preset release >/dev/null
	@cmake --build --preset release -j $(JOBS)
	@bash bench/run_all.sh

# libFuzzer targets (clang, ASan + UBSan) run FUZZ_SECONDS each; any finding fails (fuzz/README.md).
fuzz:
	@bash scripts/deps.sh build fuzz
	@bash fuzz/run_all.sh $(FUZZ_SECONDS)

# Differential fuzzing against LinuxCNC's rs274: 500 seeded random programs (CTest runs 20).
fuzz-linuxcnc: build
	@flock /tmp/nckit-linuxcnc.lock python3 tests/programs/fuzz_linuxcnc.py --count 500 --seed 11

clean:
	@rm -rf build
