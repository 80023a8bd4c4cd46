#!/usr/bin/env bash
# The whole test suite (what CI runs): the build packages and the command
# (scripts/setup.sh), then the packages only the tests use, everything built in
# the same build/ tree and ctest; then the library and the unit tests again
# under AddressSanitizer and UndefinedBehaviorSanitizer (scripts/test_sanitized.sh,
# build-asan/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
# clang++: the generated headers are compiled with both compilers, and the
# sanitizer build uses it with its runtime (libclang-rt-14-dev, only a
# recommendation of clang, which --no-install-recommends leaves out: a fresh
# Debian 12 root then fails to link the ASan build). OpenImageIO (and oiiotool): the tests' independent
# reader of EXR and PNG. GoogleTest; Google Benchmark (scripts/benchmark.cpp
# is built so that it keeps compiling).
$SUDO apt-get install -y -qq --no-install-recommends \
  clang libclang-rt-14-dev libopenimageio-dev openimageio-tools libgtest-dev libbenchmark-dev >/dev/null
# The shader tests (tests/formats/shader_code_test.cpp, browser_furnace_test.cpp):
# glslangValidator compiles the emitted GLSL and HLSL to SPIR-V, spirv-val
# validates it; headless Chromium compiles the WGSL with Tint (WebGPU on its
# bundled SwiftShader Vulkan) and renders the WebGL2 furnace (SwiftShader GL).
$SUDO apt-get install -y -qq --no-install-recommends glslang-tools spirv-tools chromium >/dev/null
# zsh and fish: tests/cli/cli_docs_test.sh runs the generated completions in them.
$SUDO apt-get install -y -qq --no-install-recommends zsh fish >/dev/null
# numpy for Debian's python3: tests/presets/engine_generators_test.py reruns
# the engines' run-time table generators (tests/presets/engine_generators.py).
$SUDO apt-get install -y -qq --no-install-recommends python3-numpy >/dev/null
# nodejs and npm: the KTX2 test parses lutbake's .ktx2 files with the npm
# package ktx-parse, which it installs under build/npm on first use. Debian's
# packages unless a node and npm are already there (a NodeSource node 20
# conflicts with Debian's npm); without them that one test skips and says why.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null ||
    echo "test.sh: nodejs/npm could not be installed; the KTX2 reader test will skip" >&2
fi
# Tests on, and a missing test package an error rather than a smaller suite.
cmake -S . -B build -DLUTBAKE_TESTS=ON -DLUTBAKE_REQUIRE_TEST_PACKAGES=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build -j"$(nproc)" --output-on-failure --no-tests=error
bash scripts/test_sanitized.sh
