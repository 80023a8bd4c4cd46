#!/usr/bin/env bash
# examples/bake_in_process through the installed package: cmake --install
# the build into a prefix, build the example with find_package, run it, and
# hold its files to the CLI's: `lutbake bake --out out --tables E,dfg
# --format exr,header` run the same way writes the same bytes (a request
# without a commandLine records the equivalent command line).
#   example.sh <compiler> <lutbake build dir> <scratch dir>
set -euo pipefail
compiler=$1 build=$2 scratch=$3
repo="$(cd "$(dirname "$0")/../.." && pwd)"
rm -rf "$scratch"
mkdir -p "$scratch/api" "$scratch/cli"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$repo/examples/bake_in_process" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/build" -j"$(nproc)" >"$scratch/build.log" 2>&1 || { cat "$scratch/build.log"; exit 1; }
(cd "$scratch/api" && "$scratch/build/bake_in_process" out >listing.txt)
(cd "$scratch/cli" && "$scratch/prefix/bin/lutbake" bake --out out --tables E,dfg --format exr,header 2>/dev/null)
cat "$scratch/api/listing.txt"
# Four tables files (E.exr, E.h, dfg.exr, dfg.h), each with its bound
# (float32-exact), and lutbake-set.json.
[ "$(grep -c -E '/(E|dfg)\.(exr|h) ' "$scratch/api/listing.txt")" = 4 ] || { echo "expected 4 table files"; exit 1; }
grep -q '/lutbake-set.json 0$' "$scratch/api/listing.txt" || { echo "expected lutbake-set.json"; exit 1; }
awk '/\.(exr|h) / { if (!($2 > 0 && $2 < 4e-8)) { print "bound out of range: " $0; bad = 1 } } END { exit bad }' \
  "$scratch/api/listing.txt"
diff <(cd "$scratch/api/out" && ls) <(cd "$scratch/cli/out" && ls)
for f in "$scratch/cli/out"/*; do cmp "$f" "$scratch/api/out/$(basename "$f")"; done
echo "bake_in_process: $(ls "$scratch/api/out" | wc -l) files, identical to the CLI's"
