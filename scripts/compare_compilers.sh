#!/usr/bin/env bash
# Are the tables the same whichever compiler built lutbake? Builds the CLI of
# this checkout with g++ (build-gxx/) and clang++ (build-clang/), bakes every
# table in every format with each (the same command line, in directories of
# the same name, so that the recorded command lines agree too) and compares
# the files byte for byte.
#
#   bash scripts/compare_compilers.sh [JOBS]   (default 2)
#
# GXX_TREE=build reuses an existing g++ tree instead of build-gxx/, and
# CLANG_TREE=build-asan an existing clang++ one instead of build-clang/:
# scripts/test_sanitized.sh (the end of scripts/test.sh) compares the g++
# Release build with its clang++ -O1 AddressSanitizer build, which also runs
# every bake below under the sanitizers.
#
# Run alone it takes minutes (two Release builds of the library); the
# thread-count half of the determinism claim is in ctest
# (tests/cli/determinism_test.cpp). Exit 0 when every file is identical, 1
# when one differs (each is named). Every run reads the same inputs, so the
# recorded command lines agree too.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${1:-2}"
root="$PWD"
for compiler in g++ clang++; do
  command -v "$compiler" >/dev/null || { echo "compare_compilers: $compiler not found" >&2; exit 2; }
done

declare -A tree=([g++]="${GXX_TREE:-build-gxx}" [clang++]="${CLANG_TREE:-build-clang}")
for compiler in g++ clang++; do
  dir="${tree[$compiler]}"
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER="$compiler" -DCMAKE_BUILD_TYPE=Release \
      -DLUTBAKE_TESTS=OFF -DLUTBAKE_INSTALL=OFF >/dev/null
  fi
  cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$dir/CMakeCache.txt")
  clang=$("$cxx" --version | head -1 | grep -c clang || true)
  if [ "$clang" != "$([ "$compiler" = clang++ ] && echo 1 || echo 0)" ]; then
    echo "compare_compilers: $dir is not built with $compiler ($cxx)" >&2
    exit 2
  fi
  cmake --build "$dir" --target lutbake -j"$jobs" >/dev/null
done

# Every table of the registry (what `bake --tables` accepts), the 3D tables
# small, in every format with the error maps; the quadrature to a tolerance
# and the sampled estimator; Favg with each Fresnel model.
# The lists `bake --tables` and `report --tables` accept; the latter's
# sampled tables are all but ltc_ggx (its lobe error map, not a sampler).
accepted() {
  # --help wraps at 80 columns: join the lines, squeeze the spaces, then take
  # the list in --tables' brackets.
  "${tree[g++]}/lutbake" "$1" --help | tr '\n' ' ' | tr -s ' ' |
    sed -n 's/.*--tables LIST[^[]*\[comma-separated subset of: \([^]]*\)\].*/\1/p' | tr -d ' '
}
tables=$(accepted bake)
sampled=$(accepted report | tr ',' '\n' | grep -v '^ltc_' | paste -sd, -)
[ -n "$tables" ] && [ -n "$sampled" ] || { echo "compare_compilers: cannot list the tables" >&2; exit 2; }
bakes=(
  "--tables $tables --size 8 --eta-size 3 --tolerance 1e-6 --format exr,bin,header --error-map"
  "--tables $sampled --size 8 --eta-size 3 --samples 64 --format exr,bin,header --error-map"
  "--tables Favg --size 8 --fresnel dielectric --format exr,bin,header"
  "--tables Favg --size 8 --fresnel conductor --format exr,bin,header"
  "--tables Favg --size 8 --fresnel f82 --format exr,bin,header"
  "--size 32 --format exr,bin,header --error-map"
  "--tables E,Eavg,Favg,dfg,glass_E,sheen_E,sheen_Eavg,f82 --size 8 --eta-size 3 --tolerance 1e-6 --format png8,ktx2-half,dds-half,inc,js-half,ts,glsl-array,hlsl-array,wgsl-array,msl-array --shader glsl,hlsl,wgsl,msl"
  "--tables E,Eavg,Favg,dfg,glass_E,sheen_E,sheen_Eavg,f82 --size 8 --eta-size 3 --tolerance 1e-6 --format png16,ktx2,dds,inc-half,js,ts-half"
  "--preset unreal"
  "--preset godot"
  "--preset cycles --files table_ggx_E.h,table_ggx_Eavg.h,table_ggx_glass_E.h"
  "--preset eevee"
  "--preset threejs"
  "--preset filament-mobile"
)
scratch="$root/${tree[clang++]}/compare"
differ=0
compared=0
for k in "${!bakes[@]}"; do
  for compiler in g++ clang++; do
    work="$scratch/${tree[$compiler]}/$k"
    rm -rf "$work"
    mkdir -p "$work"
    # shellcheck disable=SC2086
    (cd "$work" && "$root/${tree[$compiler]}/lutbake" bake --out out ${bakes[$k]} 2>"$work/log") ||
      { cat "$work/log" >&2; exit 2; }
  done
  for file in "$scratch/${tree[g++]}/$k/out"/*; do
    name=$(basename "$file")
    other="$scratch/${tree[clang++]}/$k/out/$name"
    compared=$((compared + 1))
    if ! cmp -s "$file" "$other"; then
      echo "DIFFERS: bake ${bakes[$k]}: $name"
      differ=1
    fi
  done
  if [ "$(ls "$scratch/${tree[g++]}/$k/out")" != "$(ls "$scratch/${tree[clang++]}/$k/out")" ]; then
    echo "DIFFERS: bake ${bakes[$k]}: the file lists"
    differ=1
  fi
done
echo "compare_compilers: $(g++ --version | head -1) against $(clang++ --version | head -1):" \
  "$compared files in ${#bakes[@]} bakes, $([ $differ = 0 ] && echo "all identical" ||
  echo "some differ")"
exit $differ
