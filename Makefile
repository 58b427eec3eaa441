# The README's two commands: `make demo` and `make test`. `make demo FULL=1`: the complete study 2.
BUILD ?= build
JOBS ?= $(shell nproc)
FULL ?= 0

.PHONY: all deps build test demo bench clean

all: build

deps:
	@scripts/install-deps

build: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > /dev/null
	@cmake --build $(BUILD) -j $(JOBS) -- --no-print-directory

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: build
	@FULL=$(FULL) BUILD=$(BUILD) scripts/demo

bench: build
	@$(BUILD)/bench/inerta_bench

clean:
	rm -rf $(BUILD)
