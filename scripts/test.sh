#!/usr/bin/env bash
# The whole test suite: installs and builds (scripts/setup.sh), then ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build -j"$(nproc)" --output-on-failure
