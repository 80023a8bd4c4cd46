#!/usr/bin/env bash
# Speed benchmarks in a Release build (never part of the test suite), each
# beside its baseline measured in the same run, as medians: shared machines
# are noisy.
#   1. Google Benchmark (scripts/benchmark.cpp), 5 repetitions: the library
#      calls (bakes, one point, the samplers).
#   2. hyperfine, 10 runs after 2 warm-ups: the command a user types, the
#      process started and every file written, beside the adaptive
#      quadrature at the same bound and the sampled bake of --samples 65536.
# Usage: scripts/benchmark.sh [extra Google Benchmark flags]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target lutbake lutbake_benchmark -j"$(nproc)" >/dev/null
if ! command -v hyperfine >/dev/null; then
  SUDO=""; [ "$(id -u)" != 0 ] && SUDO=sudo
  $SUDO apt-get install -y -qq hyperfine >/dev/null
fi
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
./build/lutbake_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_display_aggregates_only=true "$@"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
hyperfine --warmup 2 --runs 10 --export-json "$scratch/cli.json" \
  -n "default bake" "./build/lutbake bake --out $scratch/a" \
  -n "adaptive quadrature, --tolerance 1e-8" \
  "./build/lutbake bake --out $scratch/b --estimator adaptive --tolerance 1e-8" \
  -n "sampled, --samples 65536" "./build/lutbake bake --out $scratch/c --samples 65536" \
  -n "eval, one point" "./build/lutbake eval --table dfg --mu 0.5 --roughness 0.5" \
  -n "dfg 512 x 512" "./build/lutbake bake --out $scratch/d --tables dfg --size 512" \
  >/dev/null
# Medians (hyperfine's own table shows means).
python3 - "$scratch/cli.json" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
base = next(r["median"] for r in results if r["command"] == "default bake")
print("| command | median | min | max | / default bake |")
print("|---|---|---|---|---|")
for r in results:
    print(f"| {r['command']} | {r['median'] * 1e3:.1f} ms | {r['min'] * 1e3:.1f} ms | "
          f"{r['max'] * 1e3:.1f} ms | {r['median'] / base:.2f} |")
PY
