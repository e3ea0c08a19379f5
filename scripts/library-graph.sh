#!/usr/bin/env bash
# Draws the link graph of rosarch's own libraries and programs (tests and third-party targets
# left out) into docs/libraries.svg, from CMake's --graphviz output of a configured build.
#   scripts/library-graph.sh [build dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --graphviz="$tmp/all.dot" "$build_dir" >/dev/null
awk '
  /label = "/ {
    match($0, /"node[0-9]+"/); id = substr($0, RSTART, RLENGTH)
    match($0, /label = "[^"]+"/); name = substr($0, RSTART + 9, RLENGTH - 10)
    if (name ~ /^rosarch/ && name != "rosarch_grammars") keep[id] = name
  }
  /->/ {
    split($0, parts, " -> "); from = parts[1]; gsub(/[ "]/, "", from)
    to = parts[2]; sub(/ .*/, "", to); gsub(/"/, "", to)
    edges[++n] = "\"" from "\"" SUBSEP "\"" to "\""
  }
  END {
    print "digraph rosarch {"
    print "  rankdir=BT; node [shape=box, fontname=\"DejaVu Sans\", fontsize=10, style=rounded];"
    for (id in keep) {
      shape = keep[id] ~ /^rosarch_/ ? "" : ", shape=ellipse"
      printf "  %s [label=\"%s\"%s];\n", id, keep[id], shape
    }
    for (i = 1; i <= n; i++) {
      split(edges[i], e, SUBSEP)
      if ((e[1] in keep) && (e[2] in keep)) printf "  %s -> %s;\n", e[1], e[2]
    }
    print "}"
  }' "$tmp/all.dot" > "$tmp/libraries.dot"
tred "$tmp/libraries.dot" > "$tmp/reduced.dot"
dot -Tsvg -o docs/libraries.svg "$tmp/reduced.dot"
[ -n "${ROSARCH_GRAPH_PNG:-}" ] && dot -Tpng -o "$ROSARCH_GRAPH_PNG" "$tmp/reduced.dot"
echo "wrote docs/libraries.svg"
