#!/usr/bin/env bash
# Fuzzes every reader and the option parsing with libFuzzer (clang, with
# AddressSanitizer and UndefinedBehaviorSanitizer), one target at a time,
# then minimises each kept corpus in tests/fuzz/corpus/TARGET (-merge=1 of
# the kept inputs and the new ones into the smallest set with the same
# coverage), which the test suite replays on every run
# (tests/formats/fuzz_corpus_test.cpp, tests/plans/fuzz_corpus_test.cpp,
# tests/cli/option_corpus_test.cpp).
#
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]   (default 120, all)
#
# Targets: scene manifest (glTF/GLB, manifests), bin exr header png ktx2 dds
# source (the table readers, each input written to an in-memory file; source
# reads every source embedding: .inc, .js/.ts, the shader arrays, c-array
# and three.js's module), cli (the options of bake, plan, eval, check,
# report, furnace and presets; one argument per line), preset (the
# preset.json that `check DIR` reads). Inputs named seed-* (tests/fuzz/make_seeds.sh) and regress-* (once
# a crash, kept after its fix) stay in the corpus whatever the merge keeps.
# A crash stops the run and leaves crash-TARGET-* in build-fuzz/; fix it,
# then copy it into the corpus as regress-*. Each target's last lines
# (cov:, ft:, executions) are in build-fuzz/logs/TARGET.log. Installs clang
# and its runtime from Debian if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  targets=(scene manifest bin exr header png ktx2 dds source cli preset)
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
if ! command -v clang++ >/dev/null || ! dpkg -s libclang-rt-dev >/dev/null 2>&1; then
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends clang libclang-rt-dev >/dev/null
fi
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLUTBAKE_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target $(printf 'lutbake_%s_fuzzer ' "${targets[@]}")
mkdir -p build-fuzz/logs
for target in "${targets[@]}"; do
  case "$target" in
    scene | manifest | preset) dict=json.dict max_len=8192 ;;
    source) dict=source.dict max_len=16384 ;;
    exr) dict=exr.dict max_len=16384 ;;
    header) dict=header.dict max_len=16384 ;;
    cli) dict=cli.dict max_len=512 ;;
    *) dict=tables.dict max_len=16384 ;;
  esac
  kept="tests/fuzz/corpus/$target"
  fresh="build-fuzz/fresh-$target"
  merged="build-fuzz/merged-$target"
  mkdir -p "$kept" "$fresh"
  # -malloc_limit_mb: an allocation over 512 MiB is a finding (the readers
  # bound what they allocate by the input's size); -timeout: a hang is one.
  # Every input takes milliseconds (stat::slowest_unit_time_sec is 0), but
  # on a shared machine a whole VM stalled for over 2 minutes during a run
  # (an input timed out in a vector's push_back), hence 300 s, not 10.
  (cd build-fuzz && "./lutbake_${target}_fuzzer" -max_total_time="$seconds" -max_len="$max_len" \
    -timeout=300 -malloc_limit_mb=512 -dict="../tests/fuzz/$dict" -print_final_stats=1 \
    -artifact_prefix="crash-$target-" "fresh-$target" "../$kept" 2>&1 |
    tee "logs/$target.log" | grep -E '^(#[0-9]+ +DONE|Done|stat::|==[0-9]+==ERROR|SUMMARY)' || true)
  if grep -qE 'ERROR: (AddressSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error' \
    "build-fuzz/logs/$target.log"; then
    echo "fuzz.sh: $target found a bug: build-fuzz/logs/$target.log, build-fuzz/crash-$target-*" >&2
    exit 1
  fi
  # The smallest set of kept and new inputs with the same coverage, plus the
  # seeds and regression inputs by name.
  rm -rf "$merged"
  mkdir -p "$merged"
  "build-fuzz/lutbake_${target}_fuzzer" -merge=1 "$merged" "$kept" "$fresh" 2>/dev/null
  find "$kept" -maxdepth 1 \( -name 'seed-*' -o -name 'regress-*' \) -exec cp {} "$merged/" \;
  rm -rf "$kept" "$fresh"
  mv "$merged" "$kept"
  echo "fuzz.sh: $target: $(ls "$kept" | wc -l) inputs, $(du -sb "$kept" | cut -f1) bytes kept"
done
