#!/usr/bin/env bash
# Runs clang-tidy with the repository's .clang-tidy over our own sources (not the fixtures, not
# the generated moc files). Needs a configured build: scripts/check-tidy.sh [build dir].
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
if [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "check-tidy: $build_dir/compile_commands.json not found; configure first (cmake --preset dev)" >&2
  exit 2
fi
jobs=$(nproc 2>/dev/null || echo 2)
run-clang-tidy -quiet -p "$build_dir" -j "$jobs" \
  '^'"$PWD"'/(model|document|widgets|app|tools)/.*\.cpp$'
