#!/usr/bin/env bash
# The library's layers (README "Layout"): each file includes lutbake headers
# only from its own layer and the layers below it.
#   core < models < integrators < tables < formats, plans < validation, presets < cli
# formats and plans are side by side, so are validation and presets: neither
# of a pair includes the other.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
rank() {
  case "$1" in
    core) echo 0 ;; models) echo 1 ;; integrators) echo 2 ;; tables) echo 3 ;;
    formats | plans) echo 4 ;; validation | presets) echo 5 ;; cli) echo 6 ;; *) echo -1 ;;
  esac
}
bad=0 checked=0
while IFS= read -r file; do
  rel=${file#"$repo"/}
  layer=$(echo "$rel" | sed -E 's#^(include/lutbake|src)/([a-z]+)/.*#\2#')
  [ "$(rank "$layer")" -ge 0 ] || continue
  checked=$((checked + 1))
  # "lutbake/LAYER/..." (public) and "LAYER/..." (private, from src/).
  while IFS= read -r included; do
    other=$(echo "$included" | sed -E 's#^(lutbake/)?([a-z_]+)/.*#\2#')
    r=$(rank "$other")
    [ "$r" -ge 0 ] || continue
    if [ "$r" -gt "$(rank "$layer")" ] || { [ "$r" -eq "$(rank "$layer")" ] && [ "$other" != "$layer" ]; }; then
      echo "$rel ($layer) includes $included ($other)"
      bad=$((bad + 1))
    fi
  done < <(grep -oE '#include "[^"]+"' "$file" | sed -E 's/#include "(.*)"/\1/')
done < <(find "$repo/include/lutbake" "$repo/src" -name '*.h' -o -name '*.cpp' | sort)
echo "$checked files checked, $bad includes against the layers"
[ "$bad" -eq 0 ] && [ "$checked" -gt 50 ]
