#!/usr/bin/env bash
# A digest of every file lutbake writes: each table of the registry in every
# format (small sizes), the shader files, the error maps, Favg under each
# Fresnel model, and every preset (Cycles without its four inside-average
# glass tables, which take minutes). Prints "sha256  bake-number/file" lines;
# two builds whose digests agree write byte-identical files. Used to prove
# that a refactor changes no output:
#
#   bash scripts/digest_outputs.sh build/lutbake > after.txt
#   diff before.txt after.txt
#
# The bakes run in a scratch directory under the same relative paths, so the
# command lines recorded in the files agree between runs.
set -euo pipefail
lutbake="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
formats="exr,bin,header,png8,ktx2,dds,inc,js,ts,glsl-array,hlsl-array,wgsl-array,msl-array"
formats2="png16,ktx2-half,dds-half,inc-half,js-half,ts-half"
bakes=(
  "--tables E,Eavg,Favg,dfg,sheen_E,sheen_Eavg,f82,glass_E,glass_Eavg,spec_E,spec_Eavg --size 6 --eta-size 3 --tolerance 1e-6 --format $formats --error-map --shader glsl,hlsl,wgsl,msl"
  "--tables E,Eavg,Favg,dfg,sheen_E,sheen_Eavg,f82,glass_E,spec_E --size 6 --eta-size 3 --tolerance 1e-6 --format $formats2,header,bin --header-type half --bin-type double"
  "--tables E,Eavg,dfg,sheen_E --size 6 --samples 64 --format exr,bin,header"
  "--tables E,Eavg,dfg --size 6 --ndf beckmann --smith separable --format exr,bin,header"
  "--tables sheen_E,sheen_Eavg --size 6 --sheen-visibility ashikhmin --sheen-alpha squared --format exr,bin,header"
  "--tables Favg --size 6 --fresnel dielectric --format exr,bin,header"
  "--tables Favg --size 6 --fresnel conductor --format exr,bin,header"
  "--tables Favg --size 6 --fresnel f82 --format exr,bin,header"
  "--size 16 --namespace my_luts"
)
presets=$("$lutbake" presets | awk '/^[^ ]/ {print $1}')
for p in $presets; do
  if [ "$p" = cycles ]; then
    bakes+=("--preset cycles --files table_ggx_E.h,table_ggx_Eavg.h,table_ggx_glass_E.h,table_ggx_glass_inv_E.h")
  else
    bakes+=("--preset $p")
  fi
done
for k in "${!bakes[@]}"; do
  mkdir -p "$scratch/$k"
  # shellcheck disable=SC2086
  (cd "$scratch/$k" && "$lutbake" bake --out out ${bakes[$k]} 2>"$scratch/$k.log" >/dev/null) ||
    { echo "digest_outputs: bake ${bakes[$k]} failed:" >&2; cat "$scratch/$k.log" >&2; exit 1; }
  (cd "$scratch/$k/out" && for f in *; do echo "$(sha256sum "$f" | cut -d' ' -f1)  $k/$f"; done)
done
