#!/usr/bin/env bash
# The whole test suite: installs and builds (scripts/setup.sh), then ctest;
# then the library and the unit tests again under AddressSanitizer and
# UndefinedBehaviorSanitizer (scripts/test_sanitized.sh, build-asan/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build -j"$(nproc)" --output-on-failure
bash scripts/test_sanitized.sh
