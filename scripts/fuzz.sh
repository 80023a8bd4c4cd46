#!/usr/bin/env bash
# Fuzzes the glTF/GLB and manifest readers with libFuzzer (clang, with
# AddressSanitizer and UndefinedBehaviorSanitizer), then merges the inputs
# that reached new code into the kept corpora in tests/fuzz/corpus/, which
# the test suite replays on every run (tests/fuzz_corpus_test.cpp).
#
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 120)
#
# A crash stops the run and leaves crash-* in build-fuzz/; copy it into the
# corpus once fixed. Installs clang and its runtime from Debian if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
if ! command -v clang++ >/dev/null || ! dpkg -s libclang-rt-dev >/dev/null 2>&1; then
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends clang libclang-rt-dev >/dev/null
fi
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLUTBAKE_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
cmake --build build-fuzz --target lutbake_scene_fuzzer lutbake_manifest_fuzzer -j"$(nproc)"
for reader in scene manifest; do
  fresh="build-fuzz/fresh-$reader"
  mkdir -p "$fresh"
  (cd build-fuzz && "./lutbake_${reader}_fuzzer" -max_total_time="$seconds" -max_len=8192 \
    -dict=../tests/fuzz/json.dict -print_final_stats=1 "../$fresh" "../tests/fuzz/corpus/$reader")
  # Keep only inputs that add coverage to what the corpus already has.
  "build-fuzz/lutbake_${reader}_fuzzer" -merge=1 "tests/fuzz/corpus/$reader" "$fresh"
done
