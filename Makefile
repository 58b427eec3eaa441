# The README's two commands: `make demo` and `make test`. `make demo FULL=1`: the complete study 2.
# `make install`: the Python module `inerta` into /usr/bin/python3's site-packages (docs/python.md).
BUILD ?= build
JOBS ?= $(shell nproc)
FULL ?= 0

.PHONY: all deps configure build cli test demo bench install python clean

all: build

deps:
	@scripts/install-deps

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS) -- --no-print-directory

# The demo needs only the program (not the tests and benchmarks): a faster first `make demo`.
cli: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta -- --no-print-directory

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: cli
	@FULL=$(FULL) BUILD=$(BUILD) scripts/demo

# The Python module alone (build/python/inerta; PYTHONPATH=build/python to use it from the build tree).
python: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta_python -- --no-print-directory

install: python
	@cmake --install $(BUILD) --component python

bench: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta_bench -- --no-print-directory
	@$(BUILD)/bench/inerta_bench

clean:
	rm -rf $(BUILD)
