#!/usr/bin/env bash
# What building and baking need, and nothing more: installs the Debian
# packages the library and the `lutbake` command build against, configures a
# Release tree in build/ and builds the library and the command only (not the
# tests). Idempotent; scripts/test.sh runs it first, then adds the test-only
# packages and builds the rest of the same tree.
set -euo pipefail
cd "$(dirname "$0")/.."
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# The compiler and build tools; OpenEXR and Imath (EXR files), TBB (threads),
# Highway (SIMD kernels), CLI11 (options), nlohmann-json (plans, presets),
# zlib (PNG). OpenImageIO, GoogleTest and Google Benchmark are the tests'
# (scripts/test.sh).
$SUDO apt-get install -y -qq --no-install-recommends \
  g++ cmake make ninja-build pkg-config \
  libopenexr-dev libimath-dev libtbb-dev libhwy-dev libcli11-dev nlohmann-json3-dev zlib1g-dev \
  >/dev/null
# Tests stay configured as they were (on by default at the top level: a tree
# that scripts/test.sh built keeps its tests); only the command is built. With
# the test packages missing the configure leaves the tests out with a warning.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target lutbake
