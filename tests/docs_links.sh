#!/usr/bin/env bash
# Every relative link of README.md and docs/*.md ([text](path), ![alt](path))
# names a file or folder that exists, resolved from the linking file's folder
# (a "#section" suffix is ignored; http(s) and mailto links are not checked;
# code, fenced or inline, holds no links).
# Prints each broken link and exits 1 if there is one. ctest Docs.LinksResolve.
set -euo pipefail
cd "$(dirname "$0")/.."
broken=0
for doc in README.md docs/*.md; do
  dir=$(dirname "$doc")
  # One link target per line: what stands between "](" and the next ")",
  # outside fenced blocks and inline code spans.
  while IFS= read -r target; do
    case "$target" in
      http://* | https://* | mailto:* | '#'*) continue ;;
    esac
    path=${target%%#*}
    if [ ! -e "$dir/$path" ]; then
      echo "$doc: broken link: $target" >&2
      broken=1
    fi
  done < <(awk '/^```/ { fenced = !fenced; next } !fenced' "$doc" | sed 's/`[^`]*`//g' |
             grep -o '](\([^)]*\))' | sed 's/^](\(.*\))$/\1/')
done
exit "$broken"
