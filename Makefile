# User entry points: `make run`, `make test`, `make bench`, `make install`. Each installs what
# it needs first.
BUILD_DIR     ?= build
PREFIX        ?= $(HOME)/.local
# What a user runs; `make run` and `make install` build only these, `make test` everything.
PROGRAMS      := meshedit meshedit-render meshedit-view
ASAN_DIR      ?= build-asan
CLANG_DIR     ?= build-clang
BENCH_DIR     ?= build-bench
JOBS          ?= $(shell nproc)
CMAKE_FLAGS   ?=

.PHONY: all deps build programs run install test test-release test-sanitize test-clang bench \
	fuzz format clean

all: build

deps:
	@./scripts/install-deps.sh

$(BUILD_DIR)/build.ninja: | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD_DIR)/build.ninja
	cmake --build $(BUILD_DIR) -j $(JOBS)

programs: deps $(BUILD_DIR)/build.ninja
	targets=$$(cmake --build $(BUILD_DIR) --target help | sed -n 's/: phony$$//p' | \
	    grep -xF $(addprefix -e ,$(PROGRAMS))); \
	    cmake --build $(BUILD_DIR) -j $(JOBS) --target $$targets

run: programs
	@./scripts/run.sh $(BUILD_DIR)

# The programs and their shaders into PREFIX (default ~/.local: bin/ is on Debian's PATH once
# it exists, after logging in again), with the C++ library (headers, static libraries, CMake
# package, meshedit.pc) and the Python module (docs/python.md), which is built here too.
LIBRARY_TARGETS := meshedit_python
install: programs
	targets=$$(cmake --build $(BUILD_DIR) --target help | sed -n 's/: phony$$//p' | \
	    grep -xF $(addprefix -e ,$(LIBRARY_TARGETS))); \
	    if [ -n "$$targets" ]; then cmake --build $(BUILD_DIR) -j $(JOBS) --target $$targets; fi
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)
	@case ":$$PATH:" in *":$(PREFIX)/bin:"*) ;; \
	    *) echo "make install: add $(PREFIX)/bin to PATH to run meshedit by name";; esac

# Every test: the Release suite (unit, CLI, golden images, the viewer under Xvfb), then the
# core, file-format and viewer command-layer tests again under ASan + UBSan.
test: test-release test-sanitize

test-release: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

test-sanitize: deps
	cmake -S . -B $(ASAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DMESHEDIT_SANITIZE=ON \
	    -DMESHEDIT_BUILD_BENCH=OFF -DMESHEDIT_BUILD_VIEWER=OFF $(CMAKE_FLAGS)
	cmake --build $(ASAN_DIR) -j $(JOBS)
	cd $(ASAN_DIR) && ctest --output-on-failure -j $(JOBS) -L "core|io|viewer"

# The second compiler: the core, file-format and edit-language tests (and what they link)
# built with clang in CLANG_DIR, warnings as errors, and run. `make test` keeps gcc.
CLANG_TESTS := mesh_tests local_ops_tests loop_tests opensubdiv_tests geometry_tests \
	bezier_tests ops_tests overlay_tests collada_tests formats_tests \
	fuzz_all
test-clang:
	./scripts/install-deps.sh --clang
	cmake -S . -B $(CLANG_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \
	    -DMESHEDIT_WERROR=ON -DMESHEDIT_BUILD_VIEWER=OFF $(CMAKE_FLAGS)
	cmake --build $(CLANG_DIR) -j $(JOBS) --target $(CLANG_TESTS)
	cd $(CLANG_DIR) && ctest --output-on-failure -j $(JOBS) -L "core|io"

# Every comparison of issue 6 (bench/README.md): installs the anchors, builds the benchmark
# programs in Release (only those; a program not declared yet is skipped by run_bench.py) and
# writes docs/performance.md. BENCH_BUDGET bounds the measurements (seconds; whatever is left
# is reported as skipped): MeshEdit's rows run at 1 thread and at all threads, so build + run
# stays under about 25 minutes on 2 cores. run_bench.py first waits for the build's load to
# settle and refuses a busy machine; BENCH_FLAGS=--allow-busy measures anyway (marked).
BENCH_TARGETS ?= bench_bandwidth bench_loop bench_ops bench_io_draw bench_build bench_local_ops bench_catmark bench_simplify bench_remesh bench_smooth bench_fill bench_editor bench_selection\
	bench_compare meshedit_python
BENCH_BUDGET  ?= 1500
BENCH_FLAGS   ?=
bench:
	./scripts/install-deps.sh --bench
	cmake -S . -B $(BENCH_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DMESHEDIT_BUILD_TESTS=OFF \
	    -DMESHEDIT_BUILD_BENCH=ON $(CMAKE_FLAGS)
	targets=$$(cmake --build $(BENCH_DIR) --target help | sed -n 's/: phony$$//p' | \
	    grep -xF $(addprefix -e ,$(BENCH_TARGETS))); \
	    cmake --build $(BENCH_DIR) -j $(JOBS) --target $$targets
	python3 bench/run_bench.py --build $(BENCH_DIR) --out docs/performance.md \
	    --budget $(BENCH_BUDGET) $(BENCH_FLAGS)

# A fuzzing campaign (docs/testing.md): every reader (round trip and parse only), the edit
# language, session files and the shader log parser under libFuzzer with ASan + UBSan for
# FUZZ_SECONDS each (default 60), or for FUZZ_RUNS executions each (the 10⁶ mode: make fuzz
# FUZZ_RUNS=1000000), FUZZ_JOBS at a time. pugixml is compiled from the source of the
# installed version so that it is instrumented too. `make test` only replays the corpus.
FUZZ_DIR      ?= build-fuzz
FUZZ_SECONDS  ?=
FUZZ_RUNS     ?=
FUZZ_JOBS     ?= $(JOBS)
FUZZ_TARGETS  ?=
FUZZ_PROGRAMS := $(foreach r,collada obj off ply stl gltf,fuzz_$(r) fuzz_$(r)_parse) fuzz_bez \
	fuzz_bzc fuzz_ops fuzz_session fuzz_shader_log
fuzz:
	./scripts/install-deps.sh --fuzz
	pugixml=$$(./scripts/fetch-pugixml-source.sh $(FUZZ_DIR)/pugixml) || \
	    { echo "make fuzz: pugixml's source is not available; its library stays uninstrumented"; \
	      pugixml=; }; \
	cmake -S . -B $(FUZZ_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	    -DCMAKE_CXX_COMPILER=clang++ -DMESHEDIT_FUZZ=ON -DMESHEDIT_BUILD_VIEWER=OFF \
	    -DMESHEDIT_PUGIXML_SOURCE=$$pugixml $(CMAKE_FLAGS)
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target $(FUZZ_PROGRAMS) meshedit
	FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_RUNS=$(FUZZ_RUNS) FUZZ_JOBS=$(FUZZ_JOBS) \
	    $(if $(FUZZ_TARGETS),FUZZ_TARGETS="$(FUZZ_TARGETS)") ./scripts/fuzz.sh $(FUZZ_DIR)

# Regenerates the sample meshes in dae/ with the project's own code (docs/samples.md).
.PHONY: samples
samples: deps $(BUILD_DIR)/build.ninja
	cmake --build $(BUILD_DIR) -j $(JOBS) --target meshedit-make-samples
	./$(BUILD_DIR)/tools/meshedit-make-samples .

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(BENCH_DIR) $(FUZZ_DIR)
