#!/usr/bin/env bash
# Regenerates scripts/report/ (report.csv, report.md, report.svg: real error
# against run time of every estimator, GGX, 32 x 32 E and dfg), the numbers
# and the plot the README shows. Usage: scripts/report.sh [budget seconds]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target lutbake -j"$(nproc)" >/dev/null
./build/lutbake report --out scripts/report --budget "${1:-60}"
