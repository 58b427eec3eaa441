# The README's two commands: `make demo` and `make test`. `make demo FULL=1`: the complete study 2.
# `make install`: the program, the Python module `inerta` (into /usr/bin/python3's site-packages) and their data
# under /usr/local (docs/install.md).
# `make fuzz FUZZ_SECONDS=60`: the fuzz targets with clang's libFuzzer; `make sanitize`: the test
# suite built with clang's ASan + UBSan (docs/fuzzing.md). Both in their own build directories.
BUILD ?= build
JOBS ?= $(shell nproc)
FULL ?= 0

.PHONY: all deps configure build cli test demo bench install python clean fuzz fuzz-build sanitize clang-deps

all: build

deps:
	@scripts/install-deps

# Ninja for a new build directory (objects compile while the libraries they link are still being
# archived: ≈ 1 min less on a fresh clone, docs/benchmarks.md); an existing one keeps its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

configure: deps
	@cmake -S . -B $(BUILD) $(call generator,$(BUILD)) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The demo needs only the program (not the tests and benchmarks): a faster first `make demo`.
cli: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

demo: cli
	@FULL=$(FULL) BUILD=$(BUILD) scripts/demo

# The Python module alone (build/python/inerta; PYTHONPATH=build/python to use it from the build tree).
python: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta_python

install: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta inerta_python
	@cmake --install $(BUILD) --component python

bench: configure
	@cmake --build $(BUILD) -j $(JOBS) --target inerta_bench
	@$(BUILD)/bench/inerta_bench

# clang builds (docs/fuzzing.md). -fno-sanitize-recover: a UBSan report fails the run.
# clang 16: Debian 12's clang 14 rejects C++20 lambda captures of structured bindings (src/optim).
CLANGXX ?= clang++-16
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?=
SANITIZE_BUILD ?= build-sanitize
SANITIZERS := -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer

clang-deps:
	@scripts/install-deps --clang

# Everything instrumented for coverage (fuzzer-no-link) and ASan + UBSan, assertions on; only the
# fuzz targets (and the libraries they link) are built. Line tables only: a finding's stack still names file
# and line, and the build is ≈ 15–30 % faster than with -g (docs/fuzzing.md).
fuzz-build: clang-deps
	@cmake -S . -B $(FUZZ_BUILD) $(call generator,$(FUZZ_BUILD)) -DCMAKE_CXX_COMPILER=$(CLANGXX) -DINERTA_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $(SANITIZERS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZERS)" > /dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target inerta_fuzz

fuzz: fuzz-build
	@scripts/fuzz $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# Everything (library, CLI, tests, Python module) with ASan + UBSan and the shared ASan runtime (so
# that the Python tests can preload it into /usr/bin/python3), then the whole test suite.
ASAN_RT = $(shell $(CLANGXX) -print-file-name=libclang_rt.asan-x86_64.so)
SANITIZE_LINK = $(SANITIZERS) -shared-libasan -Wl,-rpath,$(dir $(ASAN_RT))
sanitize: clang-deps
	@cmake -S . -B $(SANITIZE_BUILD) $(call generator,$(SANITIZE_BUILD)) -DCMAKE_CXX_COMPILER=$(CLANGXX) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g" -DCMAKE_CXX_FLAGS="$(SANITIZERS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="$(SANITIZE_LINK)" -DCMAKE_SHARED_LINKER_FLAGS="$(SANITIZE_LINK)" \
	  -DCMAKE_MODULE_LINKER_FLAGS="$(SANITIZE_LINK)" > /dev/null
	@cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	@ASAN_RT=$(ASAN_RT) JOBS=$(JOBS) scripts/sanitize-test $(SANITIZE_BUILD)

clean:
	rm -rf $(BUILD)
