#!/usr/bin/env bash
# Speed benchmarks in a Release build (never part of the test suite). Each
# is repeated and the median reported: shared machines are noisy. The
# default bake alone takes ~1.5 min on 2 cores, so the whole run takes
# several minutes. Usage: scripts/benchmark.sh [extra Google Benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target lutbake_benchmark -j"$(nproc)" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
./build/lutbake_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_display_aggregates_only=true "$@"
