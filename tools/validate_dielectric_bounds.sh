#!/bin/bash
# The dielectric albedo rule's bounds against the adaptive reference on 9216
# points (tools/validate_dielectric_bounds.cpp). References are computed once
# into REFERENCE (one process per point, each cut off after LIMIT seconds:
# at some points the adaptive rule takes minutes), then the rule is checked.
#   tools/validate_dielectric_bounds.sh BUILD_DIR REFERENCE [LIMIT=5] [JOBS=2]
set -euo pipefail
tool="$1/lutbake_validate_dielectric"
reference="$2"
limit="${3:-5}"
jobs="${4:-2}"
if [ ! -s "$reference" ]; then
  seq 0 9215 | xargs -P "$jobs" -I{} timeout "$limit" "$tool" --point {} >> "$reference" || true
fi
"$tool" --reference "$reference"
