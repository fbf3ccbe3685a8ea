# Front door: every target installs what is missing, configures and builds first.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=
CTEST_FLAGS ?= --output-on-failure

.PHONY: all deps build demo test bench docs format clean sanitize-test

all: build

deps-%:
	@scripts/install-deps.sh $*

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_FLAGS)

configure: $(BUILD_DIR)/CMakeCache.txt

build: deps-build
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	$(BUILD_DIR)/bin/mink demo

test: deps-test
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DMINK_BUILD_TESTS=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)
	ctest --test-dir $(BUILD_DIR) -j $(JOBS) $(CTEST_FLAGS)

# The same tests under AddressSanitizer + UndefinedBehaviorSanitizer, in their own build dir.
sanitize-test: deps-test
	$(MAKE) test BUILD_DIR=build-asan BUILD_TYPE=RelWithDebInfo \
	  CMAKE_FLAGS="$(CMAKE_FLAGS) -DMINK_SANITIZE=ON"

bench: deps-bench
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DMINK_BUILD_BENCH=ON $(CMAKE_FLAGS)
	cmake --build $(BUILD_DIR) -j $(JOBS)
	bench/run.sh $(BUILD_DIR)

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
	rm -rf $(BUILD_DIR) build-asan
