#!/usr/bin/env bash
# Speed benchmarks in a Release build (never part of the test suite), each
# beside its baseline measured in the same run, as medians: shared machines
# are noisy.
#   1. Google Benchmark (scripts/benchmark.cpp), 5 repetitions: the library
#      calls (bakes, one point, the samplers).
#   2. hyperfine, 10 runs after 2 warm-ups: the command a user types, the
#      process started and every file written, beside the adaptive
#      quadrature at the same bound and the sampled bake of --samples 65536.
#   3. Every table's default bake, `bake --preset cycles` and `check` of the
#      default set and of a default glass set, each timed (median of RUNS,
#      default 3) right after the scalar baseline of the same run: a plain
#      sampled DFG bake (`bake --tables dfg --estimator vndf-random --samples
#      1024`, independent random points, scalar estimator); the ratio to it
#      is the number to compare across machines.
# Usage: scripts/benchmark.sh [--tables-only] [extra Google Benchmark flags]
#   --tables-only: part 3 alone. Environment: RUNS=N its runs (default 3),
#   ONLY=REGEX only the rows whose name matches (e.g. ONLY='^(glass|spec)_E$').
set -euo pipefail
cd "$(dirname "$0")/.."
tables_only=0
if [ "${1:-}" = "--tables-only" ]; then
  tables_only=1
  shift
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target lutbake -j"$(nproc)" >/dev/null

# Part 3: seconds of one run of "$@" (wall clock).
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
every_table() {
  local runs="${RUNS:-3}" scratch name cmd base t b
  scratch="$(mktemp -d)"
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
  echo "baseline: lutbake bake --tables dfg --estimator vndf-random --samples 1024 (median of $runs, each run beside the measured one)"
  echo
  echo "| what | median | baseline median, same runs | ratio |"
  echo "|---|---|---|---|"
  ./build/lutbake bake --out "$scratch/glass" --tables glass_E,glass_Eavg --size 8 --eta-size 3 >/dev/null 2>&1
  ./build/lutbake bake --out "$scratch/default" >/dev/null 2>&1
  local -a names=(E Eavg Favg dfg f82 sheen_E sheen_Eavg glass_E glass_Eavg spec_E spec_Eavg
                  oren_nayar_E oren_nayar_full_E ltc_ggx "default set (E,Eavg,Favg,dfg)"
                  "preset cycles" "preset threejs-ltc"
                  "check default set" "check glass_E,glass_Eavg (8 x 8 x 3)")
  for name in "${names[@]}"; do
    if [ -n "${ONLY:-}" ] && ! [[ "$name" =~ $ONLY ]]; then continue; fi
    case "$name" in
      "default set"*) cmd=(./build/lutbake bake --out "$scratch/t") ;;
      "preset "*) cmd=(./build/lutbake bake --out "$scratch/t" --preset "${name#preset }") ;;
      "check default set") cmd=(./build/lutbake check "$scratch/default") ;;
      "check glass"*) cmd=(./build/lutbake check "$scratch/glass") ;;
      *) cmd=(./build/lutbake bake --out "$scratch/t" --tables "$name") ;;
    esac
    : >"$scratch/times"
    : >"$scratch/base"
    for _ in $(seq "$runs"); do
      seconds ./build/lutbake bake --out "$scratch/b" --tables dfg --estimator vndf-random \
        --samples 1024 >>"$scratch/base"
      seconds "${cmd[@]}" >>"$scratch/times"
      rm -rf "$scratch/t" "$scratch/b"
    done
    t=$(median <"$scratch/times")
    b=$(median <"$scratch/base")
    printf '| %s | %.3g s | %.3g s | %.3gx |\n' "$name" "$t" "$b" "$(echo "$t / $b" | bc -l)"
  done
  rm -rf "$scratch"
}
if [ "$tables_only" = 1 ]; then
  every_table
  exit 0
fi
cmake --build build --target lutbake_benchmark -j"$(nproc)" >/dev/null
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
echo
every_table
