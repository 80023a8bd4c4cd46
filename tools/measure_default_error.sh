#!/usr/bin/env bash
# Measures the real error of the default bake against the quadrature
# reference (a long run: the default dfg alone takes ~1.5 min on 2 cores, and
# the reference ~20 ms per texel). Usage: tools/measure_default_error.sh [samples]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build --target lutbake_measure >/dev/null
./build/lutbake_measure "${1:-65536}"
