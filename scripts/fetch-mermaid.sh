#!/usr/bin/env bash
# Installs Mermaid's own parser (and jsdom, which it needs outside a browser) into <dest>, at
# the versions and integrity hashes pinned in tests/support/mermaid/package-lock.json, from
# the npm registry. The tests parse every Mermaid export with it. Nothing is committed.
set -euo pipefail
dest=${1:?usage: fetch-mermaid.sh <dest-dir>}
src="$(cd "$(dirname "$0")/.." && pwd)/tests/support/mermaid"
mkdir -p "$dest"
sum=$(cat "$src/package.json" "$src/package-lock.json" | sha256sum | cut -d' ' -f1)
if [ -f "$dest/.sha256" ] && [ "$(cat "$dest/.sha256")" = "$sum" ] && [ -d "$dest/node_modules/mermaid" ]; then
  exit 0
fi
echo "fetch-mermaid: npm ci (mermaid, jsdom)"
cp "$src/package.json" "$src/package-lock.json" "$dest/"
(cd "$dest" && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
echo "$sum" > "$dest/.sha256"
