# Front door: every target installs what is missing, configures and builds first.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
CTEST_FLAGS ?= --output-on-failure
# The Python the module is built for and tested with: Debian's, whatever else is on PATH.
PYTHON ?= $(shell test -x /usr/bin/python3 && echo /usr/bin/python3 || command -v python3)
CONFIGURE = cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DPython3_EXECUTABLE=$(PYTHON)

.PHONY: all deps build python demo test bench docs format clean sanitize-test tsan-test soak lockstep fuzz

all: build

deps-%:
	@scripts/install-deps.sh $*

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_FLAGS)

configure: $(BUILD_DIR)/CMakeCache.txt

build: deps-build
	$(CONFIGURE) $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The Python module alone, in BUILD_DIR/python (import it with PYTHONPATH=BUILD_DIR/python);
# a new build directory leaves the tests out (they need the test packages).
python: deps-python
	$(CONFIGURE) $(if $(wildcard $(BUILD_DIR)/CMakeCache.txt),,-DMINK_BUILD_TESTS=OFF) $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target python
	@echo "minkowski built in $(abspath $(BUILD_DIR))/python:"
	@echo "  export PYTHONPATH=$(abspath $(BUILD_DIR))/python; $(PYTHON) -c 'import minkowski'"

# The default scene headless (video, a few frames, stats), the paper's figures and a Box2D
# comparison with its plot, all under out/.
demo: deps-test
	$(CONFIGURE) $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target mink
	mkdir -p out/frames
	$(BUILD_DIR)/bin/mink run tumbler_400 --seconds 10 --video out/demo.mp4 --stats out/stats.csv \
	  --save out/final.json --out out
	ffmpeg -loglevel error -y -i out/demo.mp4 -vf "select=not(mod(n\\,60))" -vsync vfr \
	  out/frames/frame_%02d.png
	$(BUILD_DIR)/bin/mink paper --out out/paper
	$(BUILD_DIR)/bin/mink compare tumbler_400 --steps 600 --out out/compare
	@echo
	@echo "Demo outputs:"
	@echo "  video         out/demo.mp4 (tumbler_400, 10 s)"
	@echo "  frames        out/frames/frame_*.png (every 2 s of the video)"
	@echo "  statistics    out/stats.csv (one row per step)"
	@echo "  final state   out/final.json (resume: mink run out/final.json)"
	@echo "  figures       out/paper/"
	@echo "  Box2D compare out/compare/contacts.csv and out/compare/contacts.png"
	@echo "                out/compare/trajectories.csv and out/compare/trajectories.png"

test: deps-test
	$(CONFIGURE) -DMINK_BUILD_TESTS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)
	ctest --test-dir $(BUILD_DIR) -j $(JOBS) $(CTEST_FLAGS)

# The sanitized builds (and the fuzz build) compile each library and test program in unity
# batches (CMAKE_UNITY_BUILD), which takes well under half the time of one file at a time.
SANITIZED_CMAKE_FLAGS = -DCMAKE_UNITY_BUILD=ON $(CMAKE_FLAGS)

# The same tests under AddressSanitizer + UndefinedBehaviorSanitizer, in their own build dir.
# GCC 12's runtime takes a block of dynamic thread-local storage that glibc happened to allocate
# 16 bytes into a page for one with the header glibc gave such blocks before 2.25, and reads the
# words before it as that block's bounds: now and then LeakSanitizer's exit check crashed on
# them after a test had passed (the render and command tests load libraries with such storage).
# The runtime is told to leave __tls_get_addr alone.
sanitize-test: deps-test
	ASAN_OPTIONS="$(if $(ASAN_OPTIONS),$(ASAN_OPTIONS):)intercept_tls_get_addr=0" \
	  $(MAKE) test BUILD_DIR=build-asan BUILD_TYPE=RelWithDebInfo \
	  CMAKE_FLAGS="$(SANITIZED_CMAKE_FLAGS) -DMINK_SANITIZE=ON"

# The engine tests that step on several threads (worker counts, an embedder's task system,
# snapshots taken and restored across worker counts, the soak) under ThreadSanitizer, in their
# own build dir; TSAN_TESTS='*' runs every engine test there (about 20 minutes on 2 cores).
TSAN_TESTS ?= *WorkerCounts*:TaskSystem.*:Snapshot.*:Soak.*:Divergence.StopsAre*:Continuous.FastBodiesSettled*
tsan-test: deps-test
	cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMINK_BUILD_TESTS=ON \
	  -DMINK_TSAN=ON $(SANITIZED_CMAKE_FLAGS)
	cmake --build build-tsan -j $(JOBS) --target mink_engine_tests
	TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" \
	  build-tsan/bin/mink_engine_tests --gtest_filter='$(TSAN_TESTS)'

# The full soak: 10 randomised scenes of 10^4 steps at 1 and 2 workers (see
# tests/engine/soak.hpp); the tests run a shorter one.
soak: deps-test
	$(CONFIGURE) -DMINK_BUILD_TESTS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target mink_soak
	$(BUILD_DIR)/bin/mink_soak 10 10000

# Snapshot, restore and step in lockstep for 1000 steps on every built-in scene, the big ones
# included (the tests run those for 150), a snapshot of a run at one worker restored into a run
# at two.
lockstep: deps-test
	$(CONFIGURE) -DMINK_BUILD_TESTS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target mink_engine_tests
	MINK_LOCKSTEP_FULL=1 $(BUILD_DIR)/bin/mink_engine_tests \
	  --gtest_filter='Builtins/SnapshotScenes.RestoredRunsContinueInLockstep/*'

# The libFuzzer harnesses of fuzz/ (clang 14, ASan + UBSan), in their own build dir, JOBS at a
# time, each for FUZZ_SECONDS on its seed corpus fuzz/corpus/NAME/; what they learn collects in
# build-fuzz/corpus/NAME/, a crashing input is kept as build-fuzz/artifacts/NAME/crash-* and each
# log is build-fuzz/logs/NAME.log (scripts/run-fuzzers.sh).
FUZZ_SECONDS ?= 60
FUZZ_HARNESSES ?= scene_reader point_reader overlap_line world_api snapshot_restore
fuzz: deps-fuzz
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
	  -DMINK_FUZZ=ON -DMINK_BUILD_TESTS=OFF -DMINK_WITH_RENDER=OFF -DMINK_WITH_BOX2D=OFF \
	  $(SANITIZED_CMAKE_FLAGS)
	cmake --build build-fuzz -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_HARNESSES))
	scripts/run-fuzzers.sh $(FUZZ_SECONDS) $(JOBS) $(FUZZ_HARNESSES)

bench: deps-bench
	$(CONFIGURE) -DMINK_BUILD_BENCH=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)
	PYTHON=$(PYTHON) bench/run.sh $(BUILD_DIR)

# API reference from the public headers' comments, when doxygen is installed.
docs:
	@if command -v doxygen >/dev/null 2>&1; then \
	  mkdir -p $(BUILD_DIR)/docs && MINK_DOCS_DIR=$(BUILD_DIR)/docs doxygen docs/Doxyfile && \
	  echo "API reference: $(BUILD_DIR)/docs/html/index.html"; \
	else \
	  echo "make docs: doxygen not found, no API reference built (sudo apt-get install doxygen)"; \
	fi

format:
	git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) build-asan build-tsan build-fuzz
