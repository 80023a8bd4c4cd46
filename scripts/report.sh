#!/usr/bin/env bash
# Error against run time: `lutbake report` of every estimator on GGX 32 x 32
# E and dfg (report.csv, report.md, report.svg: the real error of every texel
# against the reference, and the time each estimator takes to reach it), the
# numbers docs/accuracy-and-speed.md shows. Written into OUT_DIR (default
# build/report), never into the source tree.
# Usage: scripts/report.sh [OUT_DIR [BUDGET_SECONDS]]   (budget default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/report}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target lutbake -j"$(nproc)" >/dev/null
./build/lutbake report --out "$out" --budget "${2:-60}"
