#!/usr/bin/env bash
# The library, the CLI and the unit tests built with AddressSanitizer and
# UndefinedBehaviorSanitizer (g++, -O1, LUTBAKE_SANITIZE=ON) in build-asan/,
# then the part of the suite that is neither compiler-, install- nor
# timing-bound run under them; any report fails the run (scripts/test.sh
# calls this after the main suite; README "Reliability" has the subset and
# its time).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DLUTBAKE_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)" --target lutbake_tests lutbake
# Left out: the consumer builds and the layer check (compiler- and
# install-bound, no library code of ours runs in them under ASan), the
# byte-for-byte regeneration of luts/ and the kill, signal and determinism
# tests (minutes of full-size bakes; timing-bound), and the tests listed in
# EXCLUDED_SLOW, measured at over 20 s each under the sanitizers.
EXCLUDED='^(Consumer|Luts|Layout|Reliability|Determinism)\.'
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
ctest --test-dir build-asan -j"$(nproc)" --output-on-failure -E "$EXCLUDED" "$@"
