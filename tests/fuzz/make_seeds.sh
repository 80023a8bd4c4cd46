#!/usr/bin/env bash
# Seeds of the fuzz corpora (tests/fuzz/corpus/READER/seed-*): small tables
# written by `lutbake bake` in every format, and command lines for the cli
# target from tests/data/bad_inputs.tsv and the examples of README.md and docs/ (one
# argument per line). Run once when a corpus is started; scripts/fuzz.sh
# then grows and merges the corpora.
#
#   bash tests/fuzz/make_seeds.sh PATH/TO/lutbake
set -euo pipefail
cd "$(dirname "$0")/../.."
lutbake="$1"
corpus=tests/fuzz/corpus
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$corpus"/{bin,exr,header,png,ktx2,dds,source,cli,preset}

# 1D, 2D, two-channel and 3D tables, small and fast; PNG holds only values
# in [0, 1], which these are.
bake() {  # NAME ARGS...
  local name="$1"
  shift
  "$lutbake" bake --out "$scratch/$name" --size 4 --eta-size 2 --samples 64 --threads 1 "$@" \
    >/dev/null
}
for tables in Eavg E dfg glass_E; do
  bake "$tables" --tables "$tables" --error-map --format exr,bin,header,png16,ktx2,dds
  bake "$tables-wide" --tables "$tables" --format bin,header --bin-type double --header-type half
done
for dir in "$scratch"/*; do
  [ -d "$dir" ] || continue
  stem="$(basename "$dir")"
  for file in "$dir"/*; do
    case "$file" in
      *.bin) cp "$file" "$corpus/bin/seed-$stem-$(basename "$file")" ;;
      *.exr) cp "$file" "$corpus/exr/seed-$stem-$(basename "$file")" ;;
      *.h) cp "$file" "$corpus/header/seed-$stem-$(basename "$file")" ;;
      *.png) cp "$file" "$corpus/png/seed-$stem-$(basename "$file")" ;;
      *.ktx2) cp "$file" "$corpus/ktx2/seed-$stem-$(basename "$file")" ;;
      *.dds) cp "$file" "$corpus/dds/seed-$stem-$(basename "$file")" ;;
    esac
  done
done
# png8 and png16 (and the float / half textures) share a name: baked apart.
bake png8 --tables E,dfg --format png8
for file in "$scratch/png8"/*.png; do cp "$file" "$corpus/png/seed-png8-$(basename "$file")"; done
for half in ktx2-half dds-half; do
  bake "$half" --tables E,dfg,glass_E --format "$half"
  for file in "$scratch/$half"/*; do
    cp "$file" "$corpus/${half%-half}/seed-$half-$(basename "$file")"
  done
done

# Every source embedding (one table per run: the float32 and binary16 forms
# share a name), and the preset.json of the presets that bake in a second.
for format in inc inc-half js js-half ts-half glsl-array hlsl-array wgsl-array msl-array; do
  bake "src-$format" --tables E,glass_E --format "$format"
  for file in "$scratch/src-$format"/*; do
    cp "$file" "$corpus/source/seed-$format-$(basename "$file")"
  done
done
for preset in unreal godot cycles eevee threejs; do
  "$lutbake" bake --preset "$preset" --out "$scratch/preset-$preset" >/dev/null
  cp "$scratch/preset-$preset/preset.json" "$corpus/preset/seed-$preset.json"
done
cp "$scratch/preset-cycles/table_ggx_E.h" "$corpus/source/seed-cycles-table_ggx_E.h"

python3 - "$corpus/cli" <<'PY'
import glob, re, shlex, sys
out = sys.argv[1]
lines = []
for row in open("tests/data/bad_inputs.tsv"):
    if row.startswith("#") or not row.strip():
        continue
    fields = row.rstrip("\n").split("\t")
    if len(fields) >= 2:
        lines.append(fields[1])
for text in (t for p in ["README.md"] + sorted(glob.glob("docs/*.md")) for t in open(p)):
    m = re.match(r"^(?:\$ )?(?:\./build/)?lutbake ((?:bake|plan|eval|check|report|furnace)\b.*)$", text.strip())
    if m:
        lines.append(m.group(1).split("  #")[0])
for i, line in enumerate(lines):
    try:
        words = shlex.split(line.replace("{", "").replace("}", ""))
    except ValueError:
        continue
    with open(f"{out}/seed-{i:03d}", "w") as f:
        f.write("\n".join(words))
PY
