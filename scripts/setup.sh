#!/usr/bin/env bash
# Installs lutbake's Debian build and test dependencies, then configures and
# builds a Release tree in build/. Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  g++ clang cmake make ninja-build pkg-config \
  libopenexr-dev libimath-dev libopenimageio-dev openimageio-tools \
  libtbb-dev libhwy-dev libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev zlib1g-dev \
  >/dev/null
# The shader tests (tests/formats/shader_code_test.cpp, browser_furnace_test.cpp):
# glslangValidator compiles the emitted GLSL and HLSL to SPIR-V, spirv-val
# validates it; headless Chromium compiles the WGSL with Tint (WebGPU on its
# bundled SwiftShader Vulkan) and renders the WebGL2 furnace (SwiftShader GL).
$SUDO apt-get install -y -qq --no-install-recommends glslang-tools spirv-tools chromium >/dev/null
# numpy for Debian's python3: tests/presets/engine_generators_test.py reruns
# the engines' run-time table generators (scripts/engine_generators.py).
$SUDO apt-get install -y -qq --no-install-recommends python3-numpy >/dev/null
# nodejs and npm: the KTX2 test parses lutbake's .ktx2 files with the npm
# package ktx-parse, which it installs under build/npm on first use. Debian's
# packages unless a node and npm are already there (a NodeSource node 20
# conflicts with Debian's npm); without them that one test skips and says why.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  $SUDO apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null ||
    echo "setup.sh: nodejs/npm could not be installed; the KTX2 reader test will skip" >&2
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
