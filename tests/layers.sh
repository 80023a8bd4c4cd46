#!/usr/bin/env bash
# The library's layers (docs/layout.md): each file includes lutbake headers
# only from its own layer and the layers below it.
#   core < models < integrators < tables < formats, plans < validation, presets < api < cli
# formats and plans are side by side, so are validation and presets: neither
# of a pair includes the other. One awk pass over every file.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
cd "$repo"
find include/lutbake src \( -name '*.h' -o -name '*.cpp' \) | sort |
  xargs awk '
    BEGIN {
      split("core models integrators tables formats plans validation presets api cli", names, " ")
      split("0 1 2 3 4 4 5 5 6 7", ranks, " ")
      for (i in names) rank[names[i]] = ranks[i]
    }
    FNR == 1 {
      # include/lutbake/LAYER/... or src/LAYER/...
      layer = FILENAME
      sub(/^(include\/lutbake|src)\//, "", layer)
      if (index(layer, "/") == 0) layer = ""
      sub(/\/.*/, "", layer)
      if (layer in rank) checked++
    }
    (layer in rank) && /^[ \t]*#[ \t]*include[ \t]*"/ {
      # "lutbake/LAYER/..." (public) and "LAYER/..." (private, from src/).
      included = $0
      sub(/^[^"]*"/, "", included)
      sub(/".*/, "", included)
      other = included
      sub(/^lutbake\//, "", other)
      if (index(other, "/") == 0) next
      sub(/\/.*/, "", other)
      if (!(other in rank)) next
      if (rank[other] > rank[layer] || (rank[other] == rank[layer] && other != layer)) {
        printf "%s (%s) includes %s (%s)\n", FILENAME, layer, included, other
        bad++
      }
    }
    END {
      printf "%d files checked, %d includes against the layers\n", checked, bad
      exit !(bad == 0 && checked > 50)
    }'
