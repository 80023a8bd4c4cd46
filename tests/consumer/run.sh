#!/usr/bin/env bash
# Builds and runs the consumer (tests/consumer/) through one route:
#   run.sh package      <compiler> <lutbake build dir> <scratch dir> [standard [generator]]
#       cmake --install the build into <scratch>/prefix, then find_package
#   run.sh subdirectory <compiler> <unused>            <scratch dir>
#       add_subdirectory(<repo>) in the consumer's own build
# Then checks that the bakes rerun exactly when their inputs change: not on
# a second build, only scene_luts when its scene is touched, both when the
# OPTIONS change or (package route) the installed lutbake does.
set -euo pipefail
# standard: 17, 20, ... or "default" (the compiler's own; lutbake_add_luts
# must raise it); generator: a CMake generator name (default: Unix Makefiles).
route=$1 compiler=$2 build=$3 scratch=$4 standard=${5:-default} generator=${6:-Unix Makefiles}
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
rm -rf "$scratch"
mkdir -p "$scratch"
cp "$repo/tests/data/plans/listed.gltf" "$scratch/scene.gltf"
configure=(-S "$here" -B "$scratch/build" -G "$generator" -DCMAKE_BUILD_TYPE=Release
           -DCMAKE_CXX_COMPILER="$compiler" -DLUTBAKE_CONSUMER_SCENE="$scratch/scene.gltf")
[ "$standard" = default ] || configure+=(-DCMAKE_CXX_STANDARD="$standard")
case "$route" in
  package)
    cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
    configure+=(-DCMAKE_PREFIX_PATH="$scratch/prefix")
    ;;
  subdirectory)
    configure+=(-DLUTBAKE_SOURCE_DIR="$repo")
    ;;
  *) echo "run.sh: route '$route' is not package or subdirectory" >&2; exit 2 ;;
esac
cmake "${configure[@]}" >/dev/null
build() {  # build <log name>: builds, and prints the targets whose tables were baked
  cmake --build "$scratch/build" -j"$(nproc)" >"$scratch/$1.log" 2>&1 ||
    { cat "$scratch/$1.log"; exit 1; }
  grep -o "lutbake: baking the lookup tables of [a-z_]*" "$scratch/$1.log" |
    sed 's/.* of //' | sort | tr '\n' ' ' || true
}
expect_baked() {  # expect_baked <log name> <targets...>
  local log=$1; shift
  local got; got="$(build "$log")"; got="${got% }"
  if [ "$got" != "$*" ]; then
    echo "build '$log' baked '$got', expected '$*'"; cat "$scratch/$log.log"; exit 1
  fi
}
expect_baked first furnace scene_luts
"$scratch/build/furnace"
"$scratch/build/scene_luts"
[ ! -e "$scratch/build/lutbake_luts/scene_luts/lutbake_luts/kulla_conty.h" ] ||
  { echo "kulla_conty.h written without Eavg"; exit 1; }
expect_baked unchanged
touch "$scratch/scene.gltf"
expect_baked scene_touched scene_luts
cmake "${configure[@]}" -DLUTBAKE_CONSUMER_OPTIONS="--threads;1" >/dev/null
expect_baked options_changed furnace scene_luts
"$scratch/build/furnace" >/dev/null
# The tables of the package route come from the installed CLI.
if [ "$route" = package ]; then
  grep -rq --include=build.make --include=build.ninja "$scratch/prefix/bin/lutbake" "$scratch/build" ||
    { echo "the bake does not use the installed lutbake"; exit 1; }
  touch "$scratch/prefix/bin/lutbake"
  expect_baked cli_touched furnace scene_luts
fi
echo "consumer ($route, $(basename "$compiler"), C++ $standard, $generator): passed"
